// 14_make_reference: renders (or extends) a converged path-traced reference and keeps it
// on disk with its error bar (gi/pathtrace/reference.hpp). Not a lesson: lesson 14 and
// the radiosity lessons read what it writes. The Cornell box reference they share:
//   14_make_reference --scene cornell --width 256 --height 256 --batch-spp 4096 --batches 12
//       --out lessons/references/cornell_256x256
// Each batch draws from its own seed and is pooled with what is already there, then the
// files are rewritten: stop it at any time and the last finished batch counts; run it
// again to make the reference longer.
#include <iostream>
#include <string>

#include "gi/core/timer.hpp"
#include "gi/image/image_io.hpp"
#include "gi/pathtrace/path_scenes.hpp"
#include "gi/pathtrace/reference.hpp"
#include "gi/report/lesson.hpp"
#include "gi/report/options.hpp"
#include "gi/report/progress.hpp"

int main(int argc, char** argv) {
  return gi::run_lesson("14_make_reference", [&] {
    gi::CommonOptions common;
    std::string scene_name = "cornell", strategy = "mis";
    int width = 256, height = 256, batch_spp = 1024, batches = 1, pass_spp = 16;
    gi::PathSettings settings;
    gi::Options options("14_make_reference",
                        "Renders a path-traced reference with its standard error, or makes "
                        "the one at --out longer, batch by batch.");
    // Batch b draws from seed + b. Lessons draw from seeds 1, 2, ...: a reference made
    // from the same streams would share their noise and flatter their error.
    common.seed = 1000000;
    common.out = "out/14_path_tracing/reference_cornell_256x256";
    options.add("--out", common.out, "the reference's files: OUT.txt, OUT.pfm, OUT_stderr.pfm (and OUT.png to look at)")
        .add("--threads", common.threads, "worker threads, 0 = all cores (the output is the same for any number)", 0,
             256)
        .add("--seed", common.seed, "seed of the first batch")
        .add("--scene", scene_name, "what to render", gi::path_scene_names())
        .add("--width", width, "image width in pixels", 1, 4096)
        .add("--height", height, "image height in pixels", 1, 4096)
        .add("--batch-spp", batch_spp, "samples per pixel in each batch", 2, 1 << 20)
        .add("--batches", batches, "batches to add", 1, 100000)
        .add("--strategy", strategy, "how paths find the light", gi::strategy_names())
        .add("--max-depth", settings.max_depth, "bounces per path", 0, 100000);
    if (!options.parse(argc, argv)) return 0;
    settings.strategy = gi::strategy_from_name(strategy);
    const gi::PathScene scene = gi::make_path_scene(gi::make_path_scene_by_name(scene_name));
    const std::string fingerprint = gi::reference_fingerprint(scene, settings, width, height);

    std::string why;
    std::optional<gi::PathReference> reference = gi::load_reference(common.out, fingerprint, &why);
    if (reference)
      std::cout << "extending " << common.out << ": " << reference->spp << " spp in " << reference->batches
                << " batches\n";
    else
      std::cout << "starting " << common.out << " (" << why << ")\n";
    for (int b = 0; b < batches; ++b) {
      const std::uint64_t seed = common.seed + (reference ? reference->batches : 0);
      gi::Film film = gi::make_film(width, height, seed);
      gi::Progress progress("batch " + std::to_string(b + 1) + "/" + std::to_string(batches), batch_spp);
      const gi::Timer timer;
      for (int done = 0; done < batch_spp; done += pass_spp) {
        const int n = std::min(pass_spp, batch_spp - done);
        gi::render_pass(film, scene, settings, n, common.threads);
        progress.advance(n);
      }
      progress.finish();
      if (film.discarded) std::cout << film.discarded << " samples were not finite and counted as 0\n";
      const gi::PathReference batch =
          gi::reference_from_film(film, scene_name, fingerprint, seed, settings, timer.seconds());
      reference = reference ? gi::combine(*reference, batch) : batch;
      gi::save_reference(*reference, common.out);
      std::cout << "batch " << b + 1 << ": " << reference->spp << " spp, " << timer.seconds() << " s; relative "
                << "standard error per pixel " << gi::relative_standard_error(*reference, 1) << '\n';
    }
    gi::write_png(reference->mean, common.out + ".png");
    return 0;
  });
}
