// Hard cases of the contact solver (label `validation`; validation/contact_hard_cases/run.sh).
// Each must converge or fail with a clear diagnosis; the table is printed for
// validation/contact_hard_cases/README.md. Independent checks per case: torque balance
// (moment of the contact forces = T1), and the physics stated in each row.
#include "base/errors.h"
#include "solve/input.h"
#include "post/position.h"

#include <deal.II/base/parameter_handler.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>

using namespace gearfem;
using namespace gearfem::contact;
using gearfem::solve::declare_gear_contact_input;
using gearfem::solve::GearContactInput;
using gearfem::solve::parse_gear_contact_input;

namespace
{
  std::string pair_text(int z1, int z2, double a, const std::string &rack_extra = "",
                        const std::string &extra = "")
  {
    std::ostringstream s;
    s << "subsection Rack\n  set Module = 3\n  set Pressure angle = 20\n" << rack_extra << "end\n"
      << "subsection Gear 1\n  set Number of teeth = " << z1 << "\n  set Face width = 20\nend\n"
      << "subsection Gear 2\n  set Number of teeth = " << z2 << "\n  set Face width = 20\nend\n"
      << "subsection Pair\n  set Centre distance = " << a << "\nend\n"
      << "subsection Mesh\n  set h_contact = 0.2\n  set h_fillet = 0.2\n  set h_coast = 0.4\nend\n" << extra;
    return s.str();
  }
  GearContactInput input(const std::string &text)
  {
    dealii::ParameterHandler prm;
    declare_gear_contact_input(prm);
    prm.parse_input_from_string(text);
    return parse_gear_contact_input(prm);
  }
  struct Row
  {
    std::string name;
    double T = 0;
    int n_pos = 0, converged = 0, max_cuts = 0, max_pairs = 0, corner_pairs = 0, unresolved = 0;
    double ste_mean = 0, ste_pp = 0, pmax = 0, balance = 0, seconds = 0;
  };
  Row sweep(const std::string &name, GearContactInput &in, double T, const std::vector<double> &phis)
  {
    Row r;
    r.name = name, r.T = T;
    const auto t0 = std::chrono::steady_clock::now();
    auto m        = in.model();
    ContactSolution prev;
    bool have = false;
    double lo = 1e300, hi = -1e300, sum = 0;
    for (const double phi : phis)
      {
        auto s = m->solve(phi, T, have ? &prev : nullptr);
        const auto p = post::evaluate_position(*m, s);
        ++r.n_pos;
        r.converged += s.solution.converged;
        r.max_cuts  = std::max(r.max_cuts, s.solution.load_cuts);
        r.max_pairs = std::max(r.max_pairs, p.n_pairs);
        for (const auto &q : p.pairs)
          {
            r.corner_pairs += q.share > 0.01 && q.edge;
            r.unresolved += q.share > 0.05 && !q.resolved;
            r.pmax = std::max(r.pmax, q.p_max);
          }
        r.balance = std::max(r.balance, std::abs(p.torque_contact / T - 1));
        lo = std::min(lo, p.ste), hi = std::max(hi, p.ste), sum += p.ste;
        prev = std::move(s.solution), have = true;
      }
    r.ste_mean = sum / r.n_pos, r.ste_pp = hi - lo;
    r.seconds  = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return r;
  }
  std::vector<double> cycle(const GearContactInput &in, int n)
  {
    return cycle_positions(*in.pair, n, 1.0, in.pair->point("A").roll_angle);
  }
  void print(const Row &r)
  {
    std::cout << std::setprecision(4) << "| " << r.name << " | " << r.T << " | " << r.converged << "/" << r.n_pos << " | "
              << r.max_cuts << " | " << r.max_pairs << " | " << r.ste_mean * 1e6 << " | " << r.ste_pp * 1e6 << " | "
              << r.pmax / 1e6 << " | " << r.corner_pairs << " | " << r.unresolved << " | " << r.balance << " | "
              << std::setprecision(3) << r.seconds << " |" << std::endl;
  }
} // namespace

TEST(HardCases, Table)
{
  std::cout << "| case | T1 [N m] | converged | load cuts | max pairs | mean STE [um] | STE p-p [um] | max p [MPa] | "
               "corner-contact pairs | unresolved pairs | max abs(M_contact/T1 - 1) | time [s] |\n"
               "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  // Very light load: the patch is far below the element size and must be reported so.
  {
    auto in = input(pair_text(50, 50, 150));
    const auto r = sweep("1 N m (patch below the element size)", in, 1.0, cycle(in, 10));
    print(r);
    EXPECT_EQ(r.converged, r.n_pos);
    EXPECT_GT(r.unresolved, 0);
  }
  // Nominal and 3x nominal (340 N m is the top Parker torque): corner contact at the tips.
  for (const double T : {340.0, 1020.0})
    {
      auto in = input(pair_text(50, 50, 150));
      const auto r = sweep(T > 500 ? "3x nominal (corner contact at the tips)" : "nominal", in, T, cycle(in, 20));
      print(r);
      EXPECT_EQ(r.converged, r.n_pos);
      if (T > 500)
        EXPECT_GT(r.corner_pairs, 0);
    }
  // Dissimilar materials: steel pinion against a 3 GPa gear (the soft gear is the slave).
  {
    auto in = input(pair_text(50, 50, 150, "",
                              "subsection Material\n  subsection Gear 2\n    set Young's modulus = 3\n"
                              "    set Poisson ratio = 0.35\n  end\nend\n"));
    EXPECT_EQ(in.contact.slave, 2);
    const auto r = sweep("steel against E = 3 GPa", in, 20.0, cycle(in, 10));
    print(r);
    EXPECT_EQ(r.converged, r.n_pos);
  }
  // High contact ratio (long addendum): at least two pairs everywhere, three at times.
  {
    auto in = input(pair_text(50, 50, 150, "  set Addendum coefficient = 1.35\n  set Dedendum coefficient = 1.6\n  set Root radius coefficient = 0.2\n"));
    std::cout << "| (contact ratio " << std::setprecision(6) << in.pair->contact_ratio() << ") | | | | | | | | | | | |\n";
    EXPECT_GT(in.pair->contact_ratio(), 2.0);
    const auto r = sweep("high contact ratio (h_a* 1.35)", in, 340.0, cycle(in, 20));
    print(r);
    EXPECT_EQ(r.converged, r.n_pos);
    EXPECT_GE(r.max_pairs, 3);
  }
  // Few pinion teeth, undercut (z 14, Z_min = 17 at x = 0). Against z 50 without shift the
  // gear tip interferes with the pinion fillet and the input is refused (named error); with
  // x1 = 0.1 against z 30 the undercut exists but stays below the active flank.
  {
    try
      {
        (void)input(pair_text(14, 50, 96));
        ADD_FAILURE() << "z 14/50 without shift should be refused (interference)";
      }
    catch (const InputError &e)
      {
        std::cout << "| z 14/50, x 0: refused (" << std::string(e.what()).substr(0, 90) << "...) | | | | | | | | | | | |\n";
      }
    auto in = input(pair_text(14, 30, 0, "", "subsection Gear 1\n  set Profile shift coefficient = 0.1\nend\n"));
    const auto r = sweep("z 14 (x 0.1, undercut) against z 30", in, 100.0, cycle(in, 20));
    print(r);
    EXPECT_EQ(r.converged, r.n_pos);
  }
  // Tip relief: STE peak-to-peak must drop at the design load. Design (Harris 1958 "long
  // relief"): linear relief from the tip down to the points of single contact, i.e. over
  // (eps_alpha - 1) p_b = 6.6 mm of the line of action on both gears, with C_a near the
  // single-pair deflection minus the double-pair one at 340 N m (~10 um). A short relief
  // (3 mm) of 15 um is shown too: at this load it widens the single-pair zone instead.
  {
    auto relief = [](double ca, double length) {
      std::ostringstream r;
      for (int g = 1; g <= 2; ++g)
        r << "subsection Gear " << g << "\n  set Tip relief = linear\n  set Tip relief amount = " << ca
          << "\n  set Tip relief length = " << length << "\nend\n";
      return r.str();
    };
    auto plain = input(pair_text(50, 50, 150));
    auto lng   = input(pair_text(50, 50, 150, "", relief(10, 6.6)));
    auto shrt  = input(pair_text(50, 50, 150, "", relief(15, 3)));
    const auto a = sweep("unmodified, 340 N m", plain, 340.0, cycle(plain, 20));
    const auto b = sweep("long linear tip relief 10 um x 6.6 mm (design 340 N m)", lng, 340.0, cycle(lng, 20));
    const auto c = sweep("short linear tip relief 15 um x 3 mm, 340 N m", shrt, 340.0, cycle(shrt, 20));
    print(a);
    print(b);
    print(c);
    EXPECT_LT(b.ste_pp, 0.5 * a.ste_pp);
  }
  // Positions exactly at A and E (a tooth entering and leaving contact).
  {
    auto in = input(pair_text(50, 50, 150));
    const auto r = sweep("positions exactly at A and E", in, 200.0,
                         {in.pair->point("A").roll_angle, in.pair->point("E").roll_angle});
    print(r);
    EXPECT_EQ(r.converged, r.n_pos);
  }
}
