#pragma once
// A plane curve given by functions of a parameter: the fillet of a generated tooth as the
// root-stress constructions (lib/rating) and the analytical models take it.
#include <functional>

namespace gearfem::analytical
{
  /// A plane curve given by functions (so that any fillet, rack-generated or not, can be
  /// used). Tooth frame: gear centre at the origin, tooth axis +y, this curve on the x > 0
  /// side or the x < 0 side (|x| is used). Units m.
  struct PlaneCurve
  {
    std::function<double(double, int)> x, y; ///< (t, derivative order 0..2)
    double t0 = 0, t1 = 1;
  };
} // namespace gearfem::analytical
