// `gearfem condense` as one library call (condensed/condense.h).
#include "condensed/condense.h"

#include <iomanip>

namespace gearfem::condensed
{
  CycleRange condense_range(const solve::GearContactInput &in, const CondenseParameters &cp)
  {
    CycleRange r = cycle_range(in.solve.torques, CycleUse::variants, cp.build_torque);
    if (cp.torque_lo > 0)
      r.lo = cp.torque_lo;
    if (cp.torque_hi > 0)
      r.hi = cp.torque_hi;
    return r;
  }

  CondensedCycle condense(const solve::GearContactInput &in, const CondenseParameters &cp, std::ostream *out)
  {
    check_condensable(in);
    const CycleRange range = condense_range(in, cp);
    auto model             = in.model();
    if (out)
      *out << "model: " << model->n_dofs() << " DoFs, set-up " << std::setprecision(3) << model->setup_seconds()
           << " s" << std::endl;
    CycleOptions options;
    options.scene_ratio = scene_ratio(CycleUse::variants, cp.scene_ratio);
    options.out         = out;
    return cycle_for(*model, in, range, options);
  }
} // namespace gearfem::condensed
