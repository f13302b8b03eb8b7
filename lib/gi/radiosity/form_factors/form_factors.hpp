#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "gi/accel/world.hpp"
#include "gi/radiosity/form_factors/form_factor_hemicube.hpp"
#include "gi/radiosity/system/form_factor_matrix.hpp"
#include "gi/radiosity/mesh/polygon.hpp"

namespace gi {

// The lecture's ways to compute a row of form factors F_ij, from one polygon i (a
// patch or an element) to every polygon j of the scene, behind one interface:
//   Differential  the differential formula from centre to centre, times H_ij from a
//                 shadow ray between the centres (form_factor_formulas.hpp); a row that
//                 would sum to more than 1 (close receivers) is scaled to sum to 1
//   Analytic      Lambert's contour integral, exact from a point, integrated over i
//                 adaptively until the error estimate meets `tolerance`
//                 (form_factor_analytic_adaptive): exact without occlusion, blind to it
//   MonteCarlo    Nusselt's analogue by sampling: rays from random points of i in
//                 cosine-distributed directions; F_ij = the fraction that hits j first
//   Hemicube      the hemicube at i's centre (form_factor_hemicube.hpp)
// Every method gives F_ii = 0, and finite values: no NaN for any valid input. A
// twisted polygon (within planarity_tolerance) is seen from its lifted centre, so
// neither it nor the elements it was cut into hide its view.
enum class FormFactorMethod { Differential, Analytic, MonteCarlo, Hemicube };
std::string name(FormFactorMethod method);  // "differential", "analytic", "monte-carlo", "hemicube"
std::vector<std::string> form_factor_method_names();
FormFactorMethod form_factor_method_from_name(const std::string& name);  // throws std::invalid_argument

struct FormFactorSettings {
  FormFactorMethod method = FormFactorMethod::Hemicube;
  int hemicube_resolution = 100;  // Hemicube: cells across the top face (even, 2..2000)
  int quadrature_order = 3;       // Analytic: the first Gauss order over the sender (1..16), doubled until converged
  int rays = 1024;                // MonteCarlo: rays per row (1..10^8), any count: n^2 stratified plus the rest at random
  bool occlusion = true;          // Differential: test visibility between the centres
  std::uint64_t seed = 1;         // MonteCarlo: row i draws from stream i of this seed
  double tolerance = 1e-10;       // Analytic: relative error of each form factor (1e-14..0.1)
};
void check(const FormFactorSettings& settings);  // throws std::invalid_argument

// What form factors are computed against: the receiving polygons (usually a mesh's
// elements, element_shapes(mesh)) and a World of them for the methods that cast rays,
// each polygon two triangles there. Throws std::invalid_argument, naming the polygon,
// for an invalid one (check), and naming both for two that overlap (overlaps.hpp).
class FormFactorScene {
 public:
  explicit FormFactorScene(std::vector<Polygon> polygons);
  const std::vector<Polygon>& polygons() const { return polygons_; }

  // The polygon a ray meets first (from either side: a back face blocks too).
  struct RayHit {
    int polygon;
    bool front;  // the ray arrives on the lit side of the triangle it hits
    double t;    // where along the ray
  };
  std::optional<RayHit> first_hit(const Ray& ray) const;

  // Can the points see each other? Nothing strictly between them (the ends excluded).
  bool visible(const vec3& from, const vec3& to) const;

  // The World the rays are cast into: polygon k is its triangles 2k and 2k + 1, in a
  // BVH (shaft.hpp gathers the few that stand near a link from it).
  const World& world() const { return world_; }

 private:
  std::vector<Polygon> polygons_;
  World world_;
};

// The ray visible() casts between two points: from `from` towards `to`, cut back at
// both ends by 1e-7 of their distance (the points' own surfaces block nothing).
// Nothing for two coincident points, which see each other.
std::optional<Ray> segment_between(const vec3& from, const vec3& to);

// F from `from` to every polygon of the scene. `row` picks the random stream
// (MonteCarlo), so that a matrix is the same for any thread count. Throws
// std::invalid_argument for bad settings or an invalid `from` (check).
std::vector<double> form_factor_row(const FormFactorScene& scene, const Polygon& from, int row,
                                    const FormFactorSettings& settings);

// A row with what each method knows about its own accuracy.
struct FormFactorRow {
  std::vector<double> F;      // F_ij for every polygon j of the scene
  std::vector<double> error;  // Analytic: each entry's error estimate; MonteCarlo: its standard error
                              // (binomial, an upper bound with stratification); empty otherwise
  int sub_cell_receivers = 0;  // Hemicube: receivers whose image is smaller than a cell (aliased)
  int sub_cell_missed = 0;     // Hemicube: of those, how many got no cell at all (F = 0)
  double sub_cell_share = 0;   // Hemicube: the share of its cells their images would cover
};
FormFactorRow form_factor_row_with_diagnostics(const FormFactorScene& scene, const Polygon& from, int row,
                                               const FormFactorSettings& settings);

// Every row, from every polygon of the scene to every other, in parallel (0: all cores).
// `hemicube`, when given, receives the hemicube's count of receivers smaller than a cell
// (left at zero by the other methods, which have no cells).
FormFactorMatrix form_factor_matrix(const FormFactorScene& scene, const FormFactorSettings& settings, int threads,
                                    HemicubeMatrixStats* hemicube = nullptr);

// Monte Carlo's row (form_factor_monte_carlo.cpp); form_factor_row calls it.
std::vector<double> form_factor_row_monte_carlo(const FormFactorScene& scene, const Polygon& from, int row,
                                                int rays, std::uint64_t seed);

}  // namespace gi
