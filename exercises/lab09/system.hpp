// Small radiosity systems the lab's tests share, the two methods written out by hand,
// and the slips students make, each computed, so that a wrong answer is told which
// slip it is (one transposed index reads as one bug, in every test).
#pragma once
#include <cmath>
#include <string>
#include <vector>

#include "gi/radiosity/system/solvers.hpp"

namespace lab09 {

using gi::Color;

// Three elements, F not symmetric, reflectances per channel: every mistake changes
// the answer.
inline gi::RadiositySystem three() {
  gi::RadiositySystem s;
  s.area = {1.0, 2.0, 0.5};
  s.rho = {Color(0.5, 0.4, 0.3), Color(0.8), Color(0.2, 0.6, 0.9)};
  s.emission = {Color(1.0), Color(0.0), Color(0.0, 0.5, 0.0)};
  s.F = {3, {0.0, 0.5, 0.2,  //
             0.25, 0.0, 0.1,  //
             0.4, 0.4, 0.0}};
  return s;
}

// Uniform reflectance above 1: more light leaves every surface than arrives.
inline gi::RadiositySystem runaway() {
  gi::RadiositySystem s;
  s.area = {1, 1, 1};
  s.rho = {Color(1.4), Color(1.4), Color(1.4)};
  s.emission = {Color(1), Color(0), Color(0)};
  s.F = {3, {0, 0.5, 0.5, 0.5, 0, 0.5, 0.5, 0.5, 0}};
  return s;
}

// The formula B_i = E_i + rho_i sum_j F_ij B_j evaluated element by element, with the
// usual slips switchable.
struct Slips {
  bool no_rho = false, no_emission = false, transposed = false, rho_of_source = false, emission_reflected = false;
};

inline Color evaluate(const gi::RadiositySystem& s, const std::vector<Color>& b, int i, Slips slips = {}) {
  Color gathered(0.0);
  for (int j = 0; j < s.size(); ++j)
    gathered += (slips.transposed ? s.F(j, i) : s.F(i, j)) * (slips.rho_of_source ? s.rho[j] : Color(1.0)) * b[j];
  const Color rho = slips.no_rho || slips.rho_of_source ? Color(1.0) : s.rho[i];
  const Color emission = slips.no_emission ? Color(0.0) : s.emission[i];
  return slips.emission_reflected ? rho * (emission + gathered) : emission + rho * gathered;
}

// One Jacobi iteration: every element from the old values only (`newest`: the slip of
// reading values written earlier in the same iteration).
inline std::vector<Color> jacobi_by_hand(const gi::RadiositySystem& s, const std::vector<Color>& old,
                                         Slips slips = {}, bool newest = false) {
  std::vector<Color> b = old, next(old.size());
  for (int i = 0; i < s.size(); ++i) {
    next[i] = evaluate(s, newest ? b : old, i, slips);
    b[i] = next[i];
  }
  return next;
}

// How a Gauss-Seidel sweep can mix old and new: `Right` is B_i <- (1 - w) B_i + w GS.
enum class Relax { Right, Swapped, WithoutOld, Ignored };

// One Gauss-Seidel sweep, in place, in order (or backwards), each element from the newest values.
inline std::vector<Color> sweep_by_hand(const gi::RadiositySystem& s, std::vector<Color> b, double omega,
                                        Slips slips = {}, Relax relax = Relax::Right, bool backwards = false,
                                        bool from_old = false) {
  const std::vector<Color> old = b;
  for (int k = 0; k < s.size(); ++k) {
    const int i = backwards ? s.size() - 1 - k : k;
    const Color gs = evaluate(s, from_old ? old : b, i, slips);
    switch (relax) {
      case Relax::Right: b[i] = (1 - omega) * b[i] + omega * gs; break;
      case Relax::Swapped: b[i] = (1 - omega) * gs + omega * b[i]; break;
      case Relax::WithoutOld: b[i] = omega * gs; break;
      case Relax::Ignored: b[i] = gs; break;
    }
  }
  return b;
}

inline bool same(const std::vector<Color>& a, const std::vector<Color>& b, double tolerance = 1e-12) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    for (int c = 0; c < 3; ++c)
      if (!(std::abs(a[i][c] - b[i][c]) <= tolerance)) return false;
  return true;
}

// What the formula's common slips say, for the message of a wrong answer.
inline std::string slip_of(const std::vector<std::pair<std::vector<Color>, const char*>>& candidates,
                           const std::vector<Color>& got, const char* otherwise) {
  for (const auto& [wrong, what] : candidates)
    if (same(got, wrong)) return what;
  return otherwise;
}

inline const char* const no_rho = "you left out rho_i: the light element i gathers is reflected by its own rho_i";
inline const char* const no_emission = "you left out E_i: an element's own emission is part of its radiosity";
inline const char* const transposed =
    "you gathered through F_ji (column i of F): element i gathers through its own row, sum_j F_ij B_j";
inline const char* const rho_of_source =
    "you reflected with rho_j of the element gathered from; the receiver's rho_i reflects what i gathers";
inline const char* const emission_reflected = "you multiplied E_i by rho_i too: only the gathered light is reflected";

// The message for a wrong Jacobi iteration from `old`.
inline std::string jacobi_slip(const gi::RadiositySystem& s, const std::vector<Color>& old,
                               const std::vector<Color>& got) {
  return slip_of({{jacobi_by_hand(s, old, {}, true),
                   "you read values written earlier in this iteration (that is Gauss-Seidel): Jacobi reads B_old only"},
                  {jacobi_by_hand(s, old, {.no_rho = true}), no_rho},
                  {jacobi_by_hand(s, old, {.no_emission = true}), no_emission},
                  {jacobi_by_hand(s, old, {.transposed = true}), transposed},
                  {jacobi_by_hand(s, old, {.rho_of_source = true}), rho_of_source},
                  {jacobi_by_hand(s, old, {.emission_reflected = true}), emission_reflected}},
                 got, "B_new_i = E_i + rho_i sum_j F_ij B_old_j, for every element i and every colour channel");
}

// The message for a wrong Gauss-Seidel sweep from `b` with relaxation `omega`.
inline std::string sweep_slip(const gi::RadiositySystem& s, const std::vector<Color>& b, double omega,
                              const std::vector<Color>& got) {
  return slip_of({{sweep_by_hand(s, b, omega, {}, Relax::Right, false, true),
                   "every element used the values from before the sweep (that is Jacobi): gather from B as it is "
                   "now, elements before i already updated in this sweep"},
                  {sweep_by_hand(s, b, omega, {}, Relax::Right, true), "sweep i = 0, 1, ..., n - 1, in order"},
                  {sweep_by_hand(s, b, omega, {.no_rho = true}), no_rho},
                  {sweep_by_hand(s, b, omega, {.no_emission = true}), no_emission},
                  {sweep_by_hand(s, b, omega, {.transposed = true}), transposed},
                  {sweep_by_hand(s, b, omega, {.rho_of_source = true}), rho_of_source},
                  {sweep_by_hand(s, b, omega, {.emission_reflected = true}), emission_reflected},
                  {sweep_by_hand(s, b, omega, {}, Relax::Swapped),
                   "relaxation swapped: B_i <- (1 - omega) B_i + omega * (the Gauss-Seidel value)"},
                  {sweep_by_hand(s, b, omega, {}, Relax::WithoutOld),
                   "relaxation without the old value: B_i <- (1 - omega) B_i + omega * (the Gauss-Seidel value)"},
                  {sweep_by_hand(s, b, omega, {}, Relax::Ignored),
                   "omega is ignored: B_i <- (1 - omega) B_i + omega * (the Gauss-Seidel value)"}},
                 got, "B_i = E_i + rho_i sum_j F_ij B_j in place, i = 0, 1, ..., each from the newest values, "
                      "then B_i <- (1 - omega) B_i + omega * that; for every colour channel");
}

// How many Jacobi iterations from B = E bring the residual below `tolerance` (relative
// to E, as the solvers measure it): counted here, not with your jacobi_iteration.
inline int jacobi_iterations_by_hand(const gi::RadiositySystem& s, double tolerance) {
  double e2 = 0;
  for (const Color& e : s.emission) e2 += gi::length_squared(e);
  std::vector<Color> b = s.emission;
  for (int k = 1; k < 100000; ++k) {
    b = jacobi_by_hand(s, b);
    double r2 = 0;
    for (const Color& r : gi::residual(s, b)) r2 += gi::length_squared(r);
    if (std::sqrt(r2 / e2) < tolerance) return k;
  }
  return 100000;
}

}  // namespace lab09
