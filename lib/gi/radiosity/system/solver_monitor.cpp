#include <algorithm>
#include <cmath>

#include "gi/core/norms.hpp"
#include "gi/radiosity/system/solver.hpp"

namespace gi {

std::string status_name(SolveStatus status) {
  switch (status) {
    case SolveStatus::Converged: return "converged";
    case SolveStatus::Diverged: return "diverged";
    case SolveStatus::StoppedAtLimit: return "stopped at the limit";
    case SolveStatus::Singular: return "singular";
  }
  return "?";
}

const SolverStep* find_step(const SolverResult& result, int step) {
  // Rows are in step order; the last one is the step the solver stopped at.
  const auto it = std::lower_bound(result.history.begin(), result.history.end(), step,
                                   [](const SolverStep& row, int s) { return row.step < s; });
  return it != result.history.end() && it->step == step ? &*it : nullptr;
}

std::string stop_reason(const SolverResult& result, const std::string& unit) {
  const int steps = result.history.empty() ? 0 : result.history.back().step;
  return status_name(result.status) + " after " + std::to_string(steps) + " " + unit + (steps == 1 ? "" : "s");
}

namespace {
double mean(const Color& c) { return (c.x + c.y + c.z) / 3; }
}  // namespace

SolverMonitor::SolverMonitor(std::string method, const RadiositySystem& system, const SolverOptions& options,
                             bool on_unshot)
    : system_(system), options_(options), on_unshot_(on_unshot) {
  result_.method = std::move(method);
  // Squares are summed scaled by a power of two near the largest E (core/norms.hpp): a
  // light of 1e-300 has squares that are 0 in double, and its residuals would all be 0.
  scale_ = power_of_two_scale(largest_channel(system.emission));
  double e2 = 0, emax = 0, p = 0;
  for (int i = 0; i < system.size(); ++i) {
    e2 += length_squared(scale_ * system.emission[i]);
    emax = std::max(emax, max_component(system.emission[i]));
    p += system.area[i] * mean(system.emission[i]);
  }
  emitted_2_ = e2 > 0 ? std::sqrt(e2) : 1;
  emitted_max_ = emax > 0 ? emax : 1;
  emitted_power_ = p > 0 ? p : 1;
}

bool SolverMonitor::stop_after(int step, const std::vector<Color>& B, const std::vector<Color>& given_r) {
  solving_seconds_ += clock_.seconds();  // the bookkeeping below is not the solver's time
  const std::vector<Color> computed = given_r.empty() ? residual(system_, B) : std::vector<Color>();
  const std::vector<Color>& r = given_r.empty() ? computed : given_r;
  SolverStep row;
  row.step = step;
  row.seconds = solving_seconds_;
  double r2 = 0, rmax = 0, unshot = 0;
  bool finite = true;
  for (int i = 0; i < system_.size(); ++i) {
    r2 += length_squared(scale_ * r[i]);
    rmax = std::max(rmax, max_component(glm::abs(r[i])));
    unshot += system_.area[i] * mean(glm::abs(r[i]));
    finite = finite && is_finite(B[i]);
  }
  row.residual_2 = std::sqrt(r2) / emitted_2_;
  row.residual_inf = rmax / emitted_max_;
  row.unshot = unshot / emitted_power_;
  if (options_.reference) {
    const std::vector<Color>& reference = *options_.reference;
    const double s = power_of_two_scale(largest_channel(reference));
    double d2 = 0, b2 = 0;
    for (int i = 0; i < system_.size(); ++i)
      d2 += length_squared(s * (B[i] - reference[i])), b2 += length_squared(s * reference[i]);
    row.error = b2 > 0 ? std::sqrt(d2 / b2) : std::sqrt(d2) / s;
  }
  if (first_residual_ < 0) first_residual_ = row.residual_2;
  // Divergence is a status, reported before the numbers turn into NaN.
  bool stop = true;
  if (!finite || !std::isfinite(row.residual_2) || row.residual_2 > 1e6 * std::max(first_residual_, 1e-12))
    result_.status = SolveStatus::Diverged;
  else if ((on_unshot_ ? row.unshot : row.residual_2) <= options_.tolerance)
    result_.status = SolveStatus::Converged;
  else if (step >= options_.max_steps)
    result_.status = SolveStatus::StoppedAtLimit;
  else
    stop = false;
  if (stop || step % options_.record_every == 0) {
    result_.history.push_back(row);
    if (options_.observer) options_.observer(row, B, r);
  }
  clock_.restart();
  return stop;
}

SolverResult SolverMonitor::fail(SolveStatus status, int step) {
  SolverStep row;
  row.step = step;
  row.residual_2 = row.residual_inf = row.unshot = NAN;
  if (options_.reference) row.error = NAN;
  row.seconds = solving_seconds_ + clock_.seconds();
  result_.history.push_back(row);
  result_.status = status;
  result_.B.assign(system_.size(), Color(NAN));
  result_.residual.assign(system_.size(), Color(NAN));
  return std::move(result_);
}

SolverResult SolverMonitor::finish(std::vector<Color> B, std::vector<Color> r) {
  result_.residual = r.empty() && system_.F.n == system_.size() ? residual(system_, B) : std::move(r);
  result_.B = std::move(B);
  return std::move(result_);
}

}  // namespace gi
