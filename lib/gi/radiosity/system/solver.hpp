#pragma once
#include <functional>
#include <string>
#include <vector>

#include "gi/core/timer.hpp"
#include "gi/radiosity/system/radiosity_system.hpp"

namespace gi {

// Every solver takes a system and these options and returns a SolverResult, so that
// all of them fit in one table and one chart.
// Singular: the direct solver met a zero pivot; B is NaN, there is no solution.
enum class SolveStatus { Converged, Diverged, StoppedAtLimit, Singular };
std::string status_name(SolveStatus status);  // "converged", "diverged", "stopped at the limit", "singular"

// One row of a solver's history, recorded after every iteration (Jacobi, Gauss-Seidel)
// or step (Southwell, progressive refinement).
struct SolverStep {
  int step = 0;
  double residual_2 = 0;     // ||r||_2 over all elements and channels, relative to ||E||_2
  double residual_inf = 0;   // max |r_i| over elements and channels, relative to max E
  double unshot = 0;         // sum_i A_i |r_i| (mean of the channels), relative to the emitted power
  double error = -1;         // RMS difference to the reference B, relative to its RMS; -1 without one
  double seconds = 0;        // since the solver started
};

struct SolverOptions {
  double tolerance = 1e-4;  // converged when residual_2 (shooting: the unshot energy) is below it
  int max_steps = 1000;     // iterations, or steps for Southwell and shooting
  const std::vector<Color>* reference = nullptr;           // for the error column
  // Called with every recorded step, the current B and its residual (for shooting,
  // the unshot radiosity): progress bars, snapshots, live pictures.
  std::function<void(const SolverStep&, const std::vector<Color>& B, const std::vector<Color>& r)> observer;
  int record_every = 1;     // history rows: every step, or every k-th (Southwell on big meshes)
};

// The history holds at least one row: the last step run. A solver may stop before
// max_steps (converged, diverged), so look steps up with find_step, not by index.
struct SolverResult {
  std::string method;
  std::vector<Color> B;
  std::vector<Color> residual;  // r at the end: for shooting, the unshot radiosity
  std::vector<SolverStep> history;
  SolveStatus status = SolveStatus::StoppedAtLimit;
};

// The history row of step `step`, or nullptr if the solver stopped before it or did
// not record it (record_every).
const SolverStep* find_step(const SolverResult& result, int step);

// "converged after 12 iterations", "stopped at the limit after 30 iterations" ...
// `unit` is what a step is called ("iteration", "step", "shot").
std::string stop_reason(const SolverResult& result, const std::string& unit);

// Records history rows and decides when to stop: converged below the tolerance,
// diverged when the residual is not finite or has grown a million-fold. Shared by
// every solver so that they measure the same things the same way.
class SolverMonitor {
 public:
  // `on_unshot`: converge on the unshot energy (shooting) rather than on residual_2.
  SolverMonitor(std::string method, const RadiositySystem& system, const SolverOptions& options,
                bool on_unshot = false);
  // Records step `step` of solution B and says whether to stop. `r` is B's residual
  // when the solver keeps it (Southwell, shooting); empty, it is computed here
  // (O(n^2), like an iteration). Time spent here is not counted as solving time.
  bool stop_after(int step, const std::vector<Color>& B, const std::vector<Color>& r = {});
  SolverResult finish(std::vector<Color> B, std::vector<Color> r = {});
  // A solver that cannot go on (a singular system): one history row of NaNs for
  // step `step`, B all NaN, and `status`.
  SolverResult fail(SolveStatus status, int step);

 private:
  SolverResult result_;
  const RadiositySystem& system_;
  const SolverOptions& options_;
  double emitted_2_ = 1, emitted_max_ = 1, emitted_power_ = 1, first_residual_ = -1;
  double scale_ = 1;  // a power of two near the largest E: squares are summed scaled by it
  double solving_seconds_ = 0;
  bool on_unshot_;
  Timer clock_;
};

}  // namespace gi
