// Hertz convergence study (label `validation`; run by validation/hertz/run.sh): both
// methods, plane stress and plane strain, equal and dissimilar discs, h = a/4 ... a/16.
// Prints the table recorded in validation/hertz/README.md and validation/RESULTS.md.
// Closed form: Johnson 1985, sec. 4.3.
// validation/hertz/check.py compares the absolute p0 and a fits with its own closed form.
#include "contact/hertz.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <iomanip>
#include <iostream>

using namespace gearfem;
using namespace gearfem::contact;

TEST(HertzConvergence, Table)
{
  struct Named
  {
    const char *name;
    HertzCase c;
  };
  std::vector<Named> cases;
  HertzCase base;
  cases.push_back({"equal, plane stress", base});
  HertzCase strain = base;
  strain.model     = fem::PlaneModel::plane_strain;
  cases.push_back({"equal, plane strain", strain});
  HertzCase dis = base;
  dis.R2 = 35e-3, dis.E2 = 110e9, dis.nu2 = 0.34;
  cases.push_back({"R2 35 mm, E2 110 GPa, plane stress", dis});
  dis.model = fem::PlaneModel::plane_strain;
  cases.push_back({"R2 35 mm, E2 110 GPa, plane strain", dis});
  const char *only = std::getenv("GEARFEM_HERTZ_QUICK");
  std::vector<double> levels = {4, 8, 16};
  if (only)
    levels = {8};
  std::cout << "| case | method | h | DoFs | active nodes | p0 fit/exact | p0 nodal/exact | a fit/exact | "
               "profile RMS/p0 | p0 fit [MPa] | a fit [mm] | geometry it | time [s] |\n"
               "|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const auto &nc : cases)
    for (const Method m : {Method::lagrange, Method::penalty})
      for (const double l : levels)
        {
          HertzCase c = nc.c;
          c.method    = m;
          c.h_contact = hertz_closed_form(c).first / l;
          const auto r = solve_hertz(c);
          std::cout << std::setprecision(4) << "| " << nc.name << " | " << to_string(m) << " | a/" << l
                    << " | " << r.n_dofs << " | " << r.n_active << " | " << r.p0_fit / r.p0_exact
                    << " | " << r.p0_nodal / r.p0_exact << " | " << r.a_fit / r.a_exact << " | "
                    << r.profile_error << " | " << std::setprecision(6) << r.p0_fit / 1e6 << " | " << r.a_fit * 1e3
                    << " | " << r.solution.geometry_iterations << " | "
                    << std::setprecision(3) << r.seconds << " |" << std::endl;
          if (l >= 8)
            {
              EXPECT_NEAR(r.p0_fit / r.p0_exact, 1.0, 0.015) << nc.name;
              EXPECT_NEAR(r.a_fit / r.a_exact, 1.0, 0.03) << nc.name;
            }
        }
}
