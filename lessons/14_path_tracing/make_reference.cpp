// 14_make_reference: renders (or extends) a converged path-traced reference and keeps it
// on disk with its error bar, as a truth (gi/render/truth.hpp). Not a lesson: lesson 14 and
// the radiosity lessons read what it writes. The Cornell box reference they share,
// lessons/references/cornell_256x256.*:
//   14_make_reference --scene cornell --width 256 --height 256 --batch-spp 4096 --batches 10
//       --out lessons/references
// Each batch draws from its own seed and is pooled with what is already there, then the
// files are rewritten: stop it at any time and the last finished batch counts; run it
// again to make the reference longer. A reference there that fails its checks is not
// replaced: one line says why, and the files are left for a person to look at.
#include <optional>
#include <stdexcept>
#include <string>

#include "gi/core/timer.hpp"
#include "gi/pathtrace/path_scenes.hpp"
#include "gi/pathtrace/path_truth.hpp"
#include "gi/report/lesson.hpp"
#include "gi/report/progress.hpp"

int main(int argc, char** argv) {
  gi::Lesson lesson("14_make_reference", "Renders a path-traced reference with its standard error, or makes "
                                         "the one in --out longer, batch by batch.");
  std::string scene_name = "cornell", strategy = "mis";
  int width = 256, height = 256, batch_spp = 1024, batches = 1;
  gi::PathSettings settings;
  lesson.add_image_size(width, height);
  lesson.options()
      .add("--scene", scene_name, "what to render", gi::path_scene_names())
      .add("--batch-spp", batch_spp, "samples per pixel in each batch", 2, 1 << 20)
      .add("--batches", batches, "batches to add", 1, 100000)
      .add("--strategy", strategy, "how paths find the light", gi::strategy_names())
      .add("--max-depth", settings.max_depth, "bounces per path", 0, 100000);
  return lesson.run(argc, argv, [&] {
    // Batch b draws from seed + 1000000 + b. Lessons draw from seeds 1, 2, ...: a
    // reference made from the same streams would share their noise and flatter their error.
    const std::uint64_t first_seed = lesson.seed() + 1000000 - 1;
    settings.strategy = gi::strategy_from_name(strategy);
    const gi::PathScene scene = gi::make_path_scene(gi::make_path_scene_by_name(scene_name));
    const gi::TruthKey key = gi::path_truth_key(scene, settings, width, height);
    const std::string stem = scene_name + "_" + std::to_string(width) + "x" + std::to_string(height);
    const std::filesystem::path file = lesson.out() / stem;

    std::string why;
    std::optional<gi::Truth> reference = gi::load_truth(file, key, &why);
    if (!reference && gi::truth_files_exist(file))
      throw std::runtime_error("not extended: " + why + "; remove its files to start afresh");
    if (reference)
      lesson.say("extending " + file.string() + ": " + std::to_string(reference->spp) + " spp in " +
                 std::to_string(reference->batches) + " batches");
    else
      lesson.say("starting " + file.string());
    for (int b = 0; b < batches; ++b) {
      const std::uint64_t seed = first_seed + (reference ? reference->batches : 0);
      gi::Film film = gi::make_film(width, height, seed);
      gi::Progress progress("batch " + std::to_string(b + 1) + "/" + std::to_string(batches), batch_spp);
      const gi::Timer timer;
      for (int done = 0; done < batch_spp; done += 16) {
        const int n = std::min(16, batch_spp - done);
        gi::path_trace(film, scene, settings, n, lesson.threads());
        progress.advance(n);
      }
      progress.finish();
      if (film.discarded) lesson.say(std::to_string(film.discarded) + " samples were not finite and counted as 0");
      const gi::Truth batch =
          gi::truth_from_film(film, key, seed, timer.seconds(), gi::path_truth_about(scene_name, settings));
      reference = reference ? gi::combine(*reference, batch) : batch;
      gi::save_truth(*reference, file);
      lesson.say("batch " + std::to_string(b + 1) + ": " + std::to_string(reference->spp) + " spp, " +
                 gi::format_number(timer.seconds(), 1, gi::Format::Fixed) + " s; relative standard error per pixel " +
                 gi::format_number(gi::relative_standard_error(reference->standard_error, reference->mean), 3, gi::Format::Scientific));
    }
    for (const auto& truth_file : gi::truth_files(file))
      lesson.record(truth_file, gi::OutputKind::Cache, "the reference's files");
    // The mean is already in stem.pfm: a PNG to look at is all the picture adds.
    lesson.diagram(reference->mean, stem + "_preview", "the reference, " + std::to_string(reference->spp) + " spp");
  });
}
