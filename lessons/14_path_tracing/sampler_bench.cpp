// 14_sampler_bench: how fast the error of each sampler falls with the number of samples,
// on four estimators whose answers are known (gi/render/sampler_study.hpp): a
// smooth integrand, a disk's indicator, and a square light's irradiance by next-event
// estimation and by cosine-weighted BSDF sampling. For N = 4 ... 4096 samples it prints
// the RMS error of a pixel's mean over many pixels, relative to the exact value, for
// independent, stratified and Owen-scrambled Sobol' samples; then the slope of each line
// on a log-log scale beside what the theory says. Not a lesson: a study the path-tracing
// lesson draws its numbers from.
//   14_sampler_bench --pixels 256 --max-samples 4096
#include <bit>
#include <string>

#include "gi/render/sampler_study.hpp"
#include "gi/core/timer.hpp"
#include "gi/report/lesson.hpp"

int main(int argc, char** argv) {
  gi::Lesson lesson("14_sampler_bench", "Error against samples for independent, stratified and Sobol' samples, "
                                        "with the fitted slopes, on four estimators with closed-form answers.");
  gi::StudySettings settings;
  int max_samples = 4096;
  lesson.options()
      .add("--pixels", settings.pixels, "independent estimates per sample count (the RMS is over them)", 16, 16384)
      .add("--max-samples", max_samples, "the largest N: N runs over the powers of 4 from 4 to it", 16, 1 << 20,
           gi::Rule{"a power of 4", [](long long n) {
                      return std::has_single_bit(std::uint64_t(n)) && std::countr_zero(std::uint64_t(n)) % 2 == 0;
                    }});
  return lesson.run(argc, argv, [&] {
    settings.seed = lesson.seed();
    settings.sample_counts.clear();
    for (std::uint32_t n = 4; n <= std::uint32_t(max_samples); n *= 4) settings.sample_counts.push_back(n);
    const std::vector<gi::SamplerKind> samplers{gi::SamplerKind::Independent, gi::SamplerKind::Stratified,
                                                gi::SamplerKind::Sobol};
    const gi::Timer timer;
    const gi::SamplerStudy study = gi::sampler_study(gi::study_estimators(), samplers, settings, lesson.threads());
    const double seconds = timer.seconds();

    std::vector<gi::Column> columns{{"estimator"}, {"N", 0}};
    for (gi::SamplerKind kind : samplers) columns.push_back({std::string(gi::sequence_name(kind)) + " RMS", 3, gi::Format::Scientific});
    gi::Table errors("Relative RMS error of the mean of N samples, over " + std::to_string(settings.pixels) + " pixels",
                     columns);
    const std::size_t counts = settings.sample_counts.size();
    for (std::size_t e = 0; e < study.rows.size() / (samplers.size() * counts); ++e)
      for (std::size_t k = 0; k < counts; ++k) {
        std::vector<gi::Cell> row{study.rows[e * samplers.size() * counts + k].estimator,
                                  settings.sample_counts[k]};
        for (std::size_t s = 0; s < samplers.size(); ++s) row.push_back(study.rows[(e * samplers.size() + s) * counts + k].rms);
        errors.add_row(row);
      }
    lesson.table(errors, "errors");

    gi::Table slopes("Slope of log RMS error against log N (fit, standard error, theory)",
                     {{"estimator"}, {"sampler"}, {"slope", 3, gi::Format::Fixed}, {"+-", 3, gi::Format::Fixed},
                      {"theory", 2, gi::Format::Fixed}});
    for (const gi::StudySlope& s : study.slopes)
      slopes.add_row({s.estimator, gi::sequence_name(s.sampler), s.slope, s.standard_error, s.expected});
    lesson.table(slopes, "slopes");
    lesson.say("study: " + gi::format_number(seconds, 2, gi::Format::Fixed) + " s on " +
               std::to_string(lesson.threads()) + " threads");
  });
}
