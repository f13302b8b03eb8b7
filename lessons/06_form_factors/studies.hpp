#pragma once
// Lesson 06, the figure of step 0 and steps 2 to 6, each a study of its own: where each method fails, as two
// squares approach, the hemicube's aliasing (failures.cpp), error against time
// (error_against_time.cpp), and one row of a room's matrix as a picture (one_row.cpp).
#include "gi/radiosity/form_factors/form_factors.hpp"
#include "gi/report/lesson.hpp"

namespace lesson06 {

// The figure of a form factor's geometry and of Nusselt's analogue, drawn from the
// numbers they stand for, and those numbers (geometry_figure.cpp).
void geometry_figure(gi::Lesson& lesson);

// The failures table: one configuration per failure, each with an exact value.
void where_each_method_fails(const gi::FormFactorSettings& base, gi::Lesson& lesson);

// The near_field table: every method's error as two unit squares approach.
void near_field(const gi::FormFactorSettings& base, gi::Lesson& lesson);

// The hemicube_aliasing table: a 5 cm square ever farther away, at four resolutions.
void hemicube_aliasing(gi::Lesson& lesson);

// The error_vs_time table and chart: each method over its parameter (Monte Carlo up to
// `most_rays` rays) on two unit squares at d = 1.
void error_against_time(int most_rays, gi::Lesson& lesson);

// One row of the Cornell box's matrix painted on the room, by the hemicube and by the
// analytic integral (one_row.cpp).
void one_row(const gi::FormFactorSettings& base, gi::Lesson& lesson);

}  // namespace lesson06
