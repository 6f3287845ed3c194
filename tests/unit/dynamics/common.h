#pragma once
// Shared factories for the dynamics tests.
#include "dynamics/analysis.h"
#include "dynamics/mesh_force.h"
#include "dynamics/models.h"

#include <limits>
#include <memory>

namespace gearfem::dynamics::test
{
  /// Kahraman & Singh (1990) reference set: zeta 0.05, F_m 0.1, k = 1 - 0.2 cos - 0.1 cos 2
  /// - 0.05 cos 3, dead zone of half-width 1 (delta = x - 1, b = 2), dimensionless time.
  inline DteModel kahraman_singh(double Omega, double zeta = 0.05, double Fm = 0.1)
  {
    auto law = std::make_unique<FourierStiffnessLaw>(1.0, 1, std::vector<double>{-0.2, -0.1, -0.05});
    ContactLogic c;
    c.backlash = 2.0;
    DteModel::Parameters p;
    p.mass = 1.0;
    p.static_force = Fm;
    p.speed = Omega;
    p.zeta = zeta;
    return DteModel(std::move(law), c, p);
  }

  /// A linear oscillator m d'' + c d' + k d = F0 (+ F_e) that stays in contact.
  inline DteModel linear_oscillator(double m, double k, double zeta, double F0,
                                    double speed = 1.0)
  {
    auto law = std::make_unique<FourierStiffnessLaw>(k, 1, std::vector<double>{});
    ContactLogic c;
    c.backlash = std::numeric_limits<double>::infinity();
    DteModel::Parameters p;
    p.mass = m;
    p.static_force = F0;
    p.zeta = zeta;
    p.speed = speed;
    return DteModel(std::move(law), c, p);
  }
} // namespace gearfem::dynamics::test
