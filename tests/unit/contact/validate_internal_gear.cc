// Validation of the internal-gear contact (label `validation`; run by
// validation/internal_gear/run.sh): a pinion z 24 inside a ring z 60, m 2 mm, x 0.3/-0.4,
// ring cut by a 20-tooth shaper, b 20 mm, steel (the pair of test_internal_contact).
//  a. Hertz at the pitch point: the pressure of the pair at C against the concave-convex
//     closed form (Johnson 1985, eqs. 4.43-4.45, 1/R = 1/rho1 - 1/rho2), three meshes.
//  b. Rim thickness: the ring's tension-side fillet peak over one mesh cycle around its
//     highest point of single contact B against the backup ratio m_B, for a rim clamped all
//     round and rims held by 6 or 12 bolts (AGMA 2001-D04 K_B for comparison).
//  c. The same FE root stress at the thick rim against ISO 6336-3 method B (rate_internal).
//  d. Equilibrium: the ring moment u T1 at a single loaded pair, the pinion bore reaction T1.
// It prints machine-readable lines `ROW,<kind>,key=value,...` (engineering units, named in
// the keys: mm, N, N m, MPa, deg) and progress lines `[i/N]`; check.py of the case applies
// the pass criteria of its README and computes the references itself.
#include "base/units.h"
#include "contact/gear_contact.h"
#include "post/position.h"
#include "rating/agma.h"
#include "rating/internal.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

using namespace gearfem;
using units::deg;
using units::mm;
using units::MPa;
using units::pi;

namespace
{
  constexpr double E_steel = 206e9, nu_steel = 0.3, b = 20 * mm;

  std::unique_ptr<geometry::InternalGearPair> make_pair()
  {
    geometry::GearParameters p;
    p.name = "Gear 1", p.teeth = 24, p.profile_shift = 0.3, p.face_width = b;
    p.rack.module = 2 * mm, p.rack.pressure_angle = 20 * deg;
    geometry::InternalGearParameters r;
    r.name = "Gear 2", r.teeth = 60, r.module = 2 * mm, r.pressure_angle = 20 * deg, r.profile_shift = -0.4;
    r.cutter.teeth = 20, r.cutter.shift = 0.0;
    return std::make_unique<geometry::InternalGearPair>(geometry::ToothProfile::generate(p),
                                                        geometry::InternalToothProfile::generate(r));
  }

  struct Materials
  {
    fem::Elasticity m[2];
    Materials()
    {
      for (auto &e : m)
        e.youngs_modulus = E_steel, e.poisson_ratio = nu_steel, e.thickness = b;
    }
  };

  /// A pinion sector of 5 teeth, teeth -1, 0, 1 fine.
  mesh::GearMeshParameters pinion_mesh(double h_contact, double h_fillet)
  {
    mesh::GearMeshParameters m;
    m.model = mesh::GearMeshParameters::Model::sector, m.sector_teeth = 5;
    m.h_contact = h_contact, m.h_fillet = h_fillet, m.h_body = 2 * mm, m.fine_teeth = "-1,0,1";
    return m;
  }

  /// One output line `ROW,kind,key=value,...`.
  class Row
  {
  public:
    explicit Row(const std::string &kind) { s_ << "ROW," << kind; }
    template <typename T>
    Row &operator()(const std::string &key, const T &value)
    {
      s_ << "," << key << "=" << value;
      return *this;
    }
    ~Row() { std::cout << s_.str() << std::endl; }

  private:
    std::ostringstream s_;
  };

  double seconds_since(std::chrono::steady_clock::time_point t0)
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }

  /// The loaded pair of ring tooth k (nullptr when it carries nothing).
  const post::ToothPairResult *ring_tooth(const post::PositionResult &r, int k)
  {
    for (const auto &tp : r.pairs)
      if (tp.gear_tooth == k)
        return &tp;
    return nullptr;
  }
} // namespace

// ---------------------------------------------------------------- a. Hertz at C

TEST(ValidateInternalGear, HertzAtThePitchPoint)
{
  const auto pair = make_pair();
  Materials mat;
  const auto &k       = pair->mesh();
  const double rho1   = k.rw1 * std::sin(k.alpha_w), rho2 = k.rw2 * std::sin(k.alpha_w);
  const double Rrel   = 1 / (1 / rho1 - 1 / rho2), Es = E_steel / 2;
  const double T_low  = 50.0, T_high = 200.0;
  // Mesh sizes from the nominal half-width at the lower torque (the whole load on the pair
  // at C): the higher torque has twice the half-width on the same meshes.
  const double P_nom = T_low / k.rb1 / b, a_nom = std::sqrt(4 * P_nom * Rrel / (pi * Es));
  Row("geometry")("z1", 24)("z2", 60)("m_mm", 2)("b_mm", b / mm)("E_GPa", E_steel / 1e9)("nu", nu_steel)(
    "alpha_w_deg", k.alpha_w / deg)("rw1_mm", k.rw1 / mm)("rw2_mm", k.rw2 / mm)("rb1_mm", k.rb1 / mm)(
    "rb2_mm", k.rb2 / mm)("a_mm", k.a / mm)("eps_alpha", k.contact_ratio)("u", pair->ratio());
  for (const auto &q : pair->line_of_action())
    Row("loa")("point", q.name)("roll_deg", q.roll_angle / deg);
  const int levels[] = {2, 4, 8};
  int i = 0;
  for (const int l : levels)
    {
      const double h = a_nom / l;
      std::cout << "[" << ++i << "/3] Hertz at C: contact size " << h / mm << " mm (a/" << l << " at " << T_low
                << " N m)" << std::endl;
      const auto t0 = std::chrono::steady_clock::now();
      mesh::RingMeshParameters ring;
      ring.model = mesh::RingMeshParameters::Model::sector, ring.sector_teeth = 5;
      ring.h_contact = h, ring.h_fillet = 0.2 * mm, ring.h_body = 2 * mm, ring.fine_teeth = "-1,0,1";
      fem::FeOptions fe;
      contact::ContactOptions opt;
      contact::GearContactModel model(*pair, pinion_mesh(h, 0.2 * mm), ring, mat.m, fe, opt);
      for (const double T1 : {T_low, T_high})
        {
          const auto s = model.solve(0.0, T1);
          const auto r = post::evaluate_position(model, s, post::PostOptions());
          const auto *c = ring_tooth(r, 0);
          ASSERT_NE(c, nullptr) << "the pair at C carries no load";
          Row("hertz")("T1_Nm", T1)("level", l)("h_mm", h / mm)("force_N", c->force)("share", c->share)(
            "n_pairs", r.n_pairs)("active_nodes", c->active_nodes)("resolved", c->resolved)("edge", c->edge)(
            "p_max_MPa", c->p_max / MPa)("p_hertz_post_MPa", c->p_hertz / MPa)("a_fit_mm", c->half_width / mm)(
            "torque_reaction_Nm", r.torque_reaction)("torque_gear_Nm", r.torque_gear)(
            "time_s", seconds_since(t0));
        }
    }
}

// ---------------------------------------------------------------- b, c, d. Rim, ISO, equilibrium

namespace
{
  /// The ring's fillet stresses of one evaluated position (displacements kept).
  struct RingRoot
  {
    double loaded = 0;       ///< max tension-side (drive) fillet sigma_1 over the loaded ring teeth [Pa]
    int loaded_tooth = 0;    ///< where (ring tooth, -1 for z - 1)
    double loaded_r = 0;     ///< radius of that peak [m]
    double loaded_share = 0; ///< load share of that tooth's pair
    double tooth0 = 0, share0 = 0; ///< the drive fillet of ring tooth 0 and its share
    double fine = 0;         ///< max over both fillets of the fine teeth -1, 0, 1 [Pa]
    int fine_tooth = 0;
    std::string fine_side;
  };

  RingRoot ring_root(const contact::GearContactModel &model, const post::PositionResult &r)
  {
    namespace bd = mesh::boundary;
    const int z  = model.pair().teeth(2);
    RingRoot out;
    out.loaded = -1e300;
    for (const auto &tp : r.pairs)
      {
        const int k = tp.gear_tooth > z / 2 ? tp.gear_tooth - z : tp.gear_tooth;
        if (tp.root_stress_gear > out.loaded)
          out.loaded = tp.root_stress_gear, out.loaded_tooth = k, out.loaded_r = tp.root_radius_gear,
          out.loaded_share = tp.share;
        if (k == 0)
          out.tooth0 = tp.root_stress_gear, out.share0 = tp.share;
      }
    out.fine = -1e300;
    for (const int k : {-1, 0, 1})
      for (const auto &[code, side] : {std::pair<bd::Code, const char *>{bd::fillet_drive, "drive"},
                                       std::pair<bd::Code, const char *>{bd::fillet_coast, "coast"}})
        {
          const auto pk = model.body(2).peak_principal_stress(r.u[1], bd::tooth_id((k + z) % z, code));
          if (pk.value > out.fine)
            out.fine = pk.value, out.fine_tooth = k, out.fine_side = side;
        }
    return out;
  }

  struct RingModel
  {
    std::string support; ///< clamped, bolts6_between, bolts6_over, bolts12_between
    int bolts        = 0;
    double phase     = 0; ///< bolt 0 from the tooth-0 axis [rad]
    double m_B       = 2;
    double h_fillet  = 0.1 * mm;
  };

  mesh::RingMeshParameters ring_mesh(const RingModel &c)
  {
    mesh::RingMeshParameters ring;
    ring.model = mesh::RingMeshParameters::Model::full_ring, ring.backup_ratio = c.m_B;
    ring.h_contact = 0.1 * mm, ring.h_fillet = c.h_fillet, ring.h_body = 2 * mm, ring.h_tooth = 0.8 * mm;
    ring.fine_teeth = "-1,0,1", ring.bolts = c.bolts, ring.bolt_phase = c.phase;
    return ring;
  }
} // namespace

TEST(ValidateInternalGear, RimThicknessIsoAndEquilibrium)
{
  const auto pair = make_pair();
  Materials mat;
  const double T1       = 100.0; // the torque of the rim study [N m]
  const double T_light  = 20.0;  // a light torque: one loaded pair over part of B..D
  const double phi_B    = pair->point("B").roll_angle, phi_D = pair->point("D").roll_angle;
  const double mid      = 0.5 * (phi_B + phi_D);
  const double pitch    = 2 * pi / pair->teeth(1); // one mesh cycle of phi1
  const std::vector<double> m_B = {2.0, 1.5, 1.2, 1.0, 0.8, 0.65, 0.5};
  std::vector<RingModel> models;
  for (const auto &[name, bolts, phase] : {std::tuple<const char *, int, double>{"clamped", 0, 0.0},
                                           {"bolts6_between", 6, pi / 6},
                                           {"bolts6_over", 6, 0.0},
                                           {"bolts12_between", 12, pi / 12}})
    for (const double mb : m_B)
      models.push_back({name, bolts, phase, mb, 0.1 * mm});
  // The fillet-mesh check of the thick clamped rim (c): half the fillet size.
  RingModel fine_fillet = models.front();
  fine_fillet.support = "clamped_fillet_h0.05", fine_fillet.h_fillet = 0.05 * mm;
  models.push_back(fine_fillet);
  // One mesh cycle around B in 0.5 deg steps (the loaded teeth are -1, 0, 1: all fine).
  std::vector<double> positions;
  for (int j = -15; j <= 15; ++j)
    positions.push_back(phi_B + j * pitch / 30);
  int i = 0;
  for (const auto &c : models)
    {
      const auto t0    = std::chrono::steady_clock::now();
      const auto ring  = ring_mesh(c);
      const double t_R = mesh::ring_rim_thickness(pair->ring(), ring), h_t = t_R / c.m_B;
      const double r_f = mesh::ring_outer_radius(pair->ring(), ring) - t_R;
      std::cout << "[" << ++i << "/" << models.size() << "] rim " << c.support << ", m_B " << c.m_B << " (t_R "
                << t_R / mm << " mm)" << std::endl;
      contact::GearContactModel model(*pair, pinion_mesh(0.1 * mm, c.h_fillet), ring, mat.m, fem::FeOptions(),
                                      contact::ContactOptions());
      const double t_setup = seconds_since(t0);
      auto evaluate        = [&](double phi, double T) {
        const auto s = model.solve(phi, T);
        auto r       = post::evaluate_position(model, s, post::PostOptions(), true);
        return std::make_pair(std::move(r), ring_root(model, r));
      };
      for (const double phi : positions)
        {
          const auto [r, rr] = evaluate(phi, T1);
          Row("rim")("support", c.support)("bolts", c.bolts)("bolt_phase_deg", c.phase / deg)("m_B", c.m_B)(
            "h_fillet_mm", c.h_fillet / mm)("t_R_mm", t_R / mm)("h_t_mm", h_t / mm)("r_f_mm", r_f / mm)(
            "K_B_lib", rating::agma::K_B(c.m_B))("T1_Nm", T1)("phi1_deg", phi / deg)("sigma_MPa", rr.loaded / MPa)(
            "tooth", rr.loaded_tooth)("height_mm", (r_f - rr.loaded_r) / mm)("share", rr.loaded_share)(
            "sigma0_MPa", rr.tooth0 / MPa)("share0", rr.share0)("sigma_fine_MPa", rr.fine / MPa)(
            "fine_tooth", rr.fine_tooth)("fine_side", rr.fine_side)("n_pairs", r.n_pairs)(
            "torque_reaction_Nm", r.torque_reaction)("torque_gear_Nm", r.torque_gear)("u", pair->ratio());
          EXPECT_GT(r.n_pairs, 0);
        }
      if (c.support == "clamped" && c.m_B == m_B.front())
        {
          // c. The thick rim at a light load from B to D: where ring tooth 0 carries the
          // load alone, its root stress per torque against ISO 6336-3.
          for (double phi = phi_B - 1 * deg; phi <= phi_D + 1e-9; phi += 0.25 * deg)
            {
              const auto [r, rr] = evaluate(phi, T_light);
              Row("iso_fe")("T1_Nm", T_light)("phi1_deg", phi / deg)("sigma0_MPa", rr.tooth0 / MPa)(
                "share0", rr.share0)("height_mm", (r_f - rr.loaded_r) / mm)("n_pairs", r.n_pairs)(
                "torque_reaction_Nm", r.torque_reaction)("torque_gear_Nm", r.torque_gear)("u", pair->ratio());
            }
          rating::InternalRatingInput in;
          in.rating.torques = {T1, T_light};
          in.rating.E1 = in.rating.E2 = E_steel, in.rating.nu1 = in.rating.nu2 = nu_steel;
          in.ring_rim_thickness = t_R;
          const auto rep = rating::rate_internal(pair->pinion(), pair->ring(), pair->mesh(), in);
          auto v = [&](const std::string &sym, std::size_t j = 0) { return rep.row("ISO 6336", sym).values.at(j); };
          for (std::size_t j = 0; j < in.rating.torques.size(); ++j)
            {
              // eq. 3 with the generated ring fillet's section (rate_internal's check rows).
              const double gen = v("F_t", j) / (b * 2 * mm) * v("Y_F2,gen") * v("Y_S2,gen") * v("Y_B2") / MPa;
              Row("iso")("T1_Nm", in.rating.torques[j])("F_t_N", v("F_t", j))("Y_F", v("Y_F2"))("Y_S", v("Y_S2"))(
                "Y_B", v("Y_B2"))("s_Fn_mm", v("s_Fn2"))("rho_F_mm", v("rho_F2"))("h_Fe_mm", v("h_Fe2"))(
                "d_en_mm", v("d_en2"))("r_f_mm", r_f / mm)("sigma_F0_MPa", v("sigma_F02", j))(
                "Y_F_gen", v("Y_F2,gen"))("Y_S_gen", v("Y_S2,gen"))("sigma_F0_gen_MPa", gen);
            }
          // d. Equilibrium in the middle of the single-pair zone at the light load.
          const auto [r, rr] = evaluate(mid, T_light);
          Row("equilibrium")("T1_Nm", T_light)("phi1_deg", mid / deg)("n_pairs", r.n_pairs)(
            "torque_contact_Nm", r.torque_contact)("torque_reaction_Nm", r.torque_reaction)(
            "torque_gear_Nm", r.torque_gear)("u", pair->ratio());
        }
      std::cout << "  set-up " << std::setprecision(3) << t_setup << " s, total " << seconds_since(t0) << " s"
                << std::setprecision(6) << std::endl;
    }
}
