#include "gearbox/life.h"

#include "geometry/limits.h"

#include "base/errors.h"

#include <algorithm>
#include <cmath>

namespace gearfem::gearbox
{
  StressTable agma_stresses(const Train &t, const fatigue::Spectrum &s, const AgmaFactors &f)
  {
    StressTable r(t.stages.size());
    for (std::size_t k = 0; k < t.stages.size(); ++k)
      {
        const Stage &st = t.stages[k];
        r[k].resize(st.meshes.size());
        for (double M : s.torques)
          {
            const double Ft = st.tangential_load(t.torques(M)[k]);
            for (std::size_t j = 0; j < st.meshes.size(); ++j)
              r[k][j].push_back(mesh_stress(st.meshes[j], Ft, f));
          }
      }
    return r;
  }

  StressTable iso_stresses(const StressTable &agma)
  {
    StressTable r = agma;
    for (auto &stage : r)
      for (auto &mesh : stage)
        for (MeshStress &m : mesh)
          {
            m.sigma_H = std::max(m.sigma_H1_iso, m.sigma_H2_iso);
            m.sigma_F1 = m.sigma_F1_iso, m.sigma_F2 = m.sigma_F2_iso;
          }
    return r;
  }

  StressTable scaled_stresses(const Train &t, const fatigue::Spectrum &s,
                              const std::vector<std::vector<MeshStress>> &at_ref, double M_ref)
  {
    require_greater("reference torque of the stress table", M_ref, 0.0, "N m");
    if (at_ref.size() != t.stages.size())
      throw InputError("reference stresses", std::to_string(at_ref.size()) + " stages",
                       std::to_string(t.stages.size()) + " stages");
    StressTable r(t.stages.size());
    for (std::size_t k = 0; k < t.stages.size(); ++k)
      {
        if (at_ref[k].size() != t.stages[k].meshes.size())
          throw InputError("reference stresses of stage " + std::to_string(k + 1),
                           std::to_string(at_ref[k].size()) + " meshes",
                           std::to_string(t.stages[k].meshes.size()) + " meshes");
        r[k].resize(at_ref[k].size());
        for (std::size_t j = 0; j < at_ref[k].size(); ++j)
          for (double M : s.torques)
            {
              const double q = M / M_ref, h = std::sqrt(q);
              const MeshStress &a = at_ref[k][j];
              r[k][j].push_back({a.sigma_H * h, a.sigma_F1 * q, a.sigma_F2 * q, a.sigma_H1_iso * h, a.sigma_H2_iso * h,
                                 a.sigma_F1_iso * q, a.sigma_F2_iso * q});
            }
      }
    return r;
  }

  namespace
  {
    struct LifeBuilder
    {
      const fatigue::Spectrum &s;
      double years_per_spectrum;
      std::vector<MemberLife> &out;
      std::size_t stage_index = 0;
      /// One entry from one or more (stress series, cycles per input revolution) pairs
      /// whose damages add up.
      void add(const std::string &stage, const std::string &member, const std::string &mode,
               const std::string &detail, const fatigue::SNCurve &c,
               const std::vector<std::pair<std::vector<double>, double>> &loads)
      {
        MemberLife m{stage, member, mode, detail, 0.0, {}, fatigue::infinite_life, {}, {}, stage_index};
        m.damage.per_bin.assign(s.torques.size(), 0.0);
        for (const auto &[sigma, per_rev] : loads)
          {
            std::vector<double> n;
            for (double rev : s.revolutions)
              n.push_back(rev * per_rev);
            const fatigue::Damage d = fatigue::miner(c, sigma, n);
            m.stress.push_back(sigma);
            m.cycles.push_back(n);
            m.damage.D += d.D;
            for (std::size_t i = 0; i < d.per_bin.size(); ++i)
              m.damage.per_bin[i] += d.per_bin[i];
            m.cycles_per_revolution = per_rev;
          }
        if (m.damage.D > 0.0)
          {
            m.damage.life_spectra = 1.0 / m.damage.D;
            m.life_years = m.damage.life_spectra * years_per_spectrum;
          }
        out.push_back(m);
      }
    };

    std::vector<double> series(const std::vector<MeshStress> &v, double MeshStress::*f)
    {
      std::vector<double> r;
      for (const MeshStress &m : v)
        r.push_back(m.*f);
      return r;
    }
  } // namespace

  std::vector<MemberLife> member_lives(const Train &t, const fatigue::Spectrum &s,
                                       const StressTable &stress,
                                       const std::vector<StageMaterial> &materials)
  {
    s.check();
    if (materials.size() != t.stages.size())
      throw InputError("Materials", std::to_string(materials.size()) + " given",
                       std::to_string(t.stages.size()) + " (one per stage)");
    std::vector<MemberLife> out;
    LifeBuilder b{s, s.duration_years, out};
    for (std::size_t k = 0; k < t.stages.size(); ++k)
      {
        const Stage &st = t.stages[k];
        const StageMaterial &mat = materials[k];
        b.stage_index = k;
        const double r = t.input_revolutions(k);
        const std::string name = st.in.name;
        const MeshGeometry &g0 = st.meshes[0];
        const auto H0 = series(stress[k][0], &MeshStress::sigma_H);
        const auto F01 = series(stress[k][0], &MeshStress::sigma_F1), F02 = series(stress[k][0], &MeshStress::sigma_F2);
        // sigma_F of a named member in mesh 0 (it may be the pinion or the gear there).
        auto F0 = [&](const std::string &member) { return g0.pinion == member ? F01 : F02; };
        if (st.in.type == StageType::parallel)
          {
            const double c1 = r * st.cycles_sun, c2 = r * st.cycles_planet;
            for (const auto &[member, c] : {std::pair<std::string, double>{"gear 1", c1}, {"gear 2", c2}})
              {
                b.add(name, member, "contact", "pair", mat.contact, {{H0, c}});
                b.add(name, member, "bending", "pair", mat.bending, {{F0(member), c}});
              }
            continue;
          }
        const auto H1 = series(stress[k][1], &MeshStress::sigma_H), F11 = series(stress[k][1], &MeshStress::sigma_F1);
        const double cs = r * st.cycles_sun, cp = r * st.cycles_planet, cr = r * st.cycles_ring;
        b.add(name, "sun", "contact", "sun-planet mesh", mat.contact, {{H0, cs}});
        b.add(name, "sun", "bending", "sun-planet mesh", mat.bending, {{F0("sun"), cs}});
        b.add(name, "planet", "contact", "sun-side flank (sun-planet mesh)", mat.contact, {{H0, cp}});
        b.add(name, "planet", "contact", "ring-side flank (planet-ring mesh)", mat.contact, {{H1, cp}});
        b.add(name, "planet", "bending", "both meshes; damages summed", mat.bending, {{F0("planet"), cp}, {F11, cp}});
        b.add(name, "ring", "contact", "planet-ring mesh", mat.contact, {{H1, cr}});
        // The ring in bending where a stress source rates it (the FE: AGMA and ISO do not).
        const auto F12 = series(stress[k][1], &MeshStress::sigma_F2);
        if (std::any_of(F12.begin(), F12.end(), [](double v) { return v > 0; }))
          b.add(name, "ring", "bending", "planet-ring mesh", mat.bending, {{F12, cr}});
      }
    return out;
  }

  ScuffingTable scuffing_table(const Train &t, const fatigue::Spectrum &s, const AgmaFactors &f,
                               const std::vector<StageMaterial> &materials,
                               const scuffing::Lubricant &oil, const scuffing::Conditions &c0)
  {
    ScuffingTable r(t.stages.size());
    const std::vector<double> n = t.speeds();
    for (std::size_t k = 0; k < t.stages.size(); ++k)
      {
        const Stage &st = t.stages[k];
        scuffing::Conditions c = c0;
        c.E1 = c.E2 = materials[k].E, c.nu1 = c.nu2 = materials[k].nu;
        c.Ra1 = c.Ra2 = materials[k].Ra;
        r[k].resize(st.meshes.size());
        for (std::size_t j = 0; j < st.meshes.size(); ++j)
          {
            const MeshGeometry &g = st.meshes[j];
            // Pinion speed relative to the carrier.
            double n1 = n[k];
            if (st.in.type == StageType::parallel)
              n1 = g.pinion == "gear 1" ? n[k] : n[k + 1];
            else
              n1 = n[k] * (g.pinion == "sun" ? st.n_sun_rel : st.n_planet_rel);
            for (double M : s.torques)
              {
                const double F = st.tangential_load(t.torques(M)[k]) * f.K_o * f.K_v * g.K_H;
                r[k][j].push_back(scuffing::evaluate(g.loa, g.module, g.internal, g.b, n1, F, oil, c));
              }
          }
      }
    return r;
  }

  Train build_train(const GearboxInput &in)
  {
    if (in.materials.size() != in.stages.size())
      throw InputError("Materials", std::to_string(in.materials.size()) + " given",
                       std::to_string(in.stages.size()) + " (one per stage)");
    Train t = build_train(in.stages, in.input_speed, in.agma);
    for (std::size_t k = 0; k < in.stages.size(); ++k)
      {
        AgmaFactors f = in.agma;
        f.E1 = f.E2 = in.materials[k].E, f.nu1 = f.nu2 = in.materials[k].nu;
        t.stages[k] = build_stage(in.stages[k], f);
      }
    return t;
  }

  namespace
  {
    int first_failure(const std::vector<MemberLife> &lives)
    {
      int first = -1;
      double shortest = fatigue::infinite_life;
      for (std::size_t i = 0; i < lives.size(); ++i)
        if (lives[i].damage.life_spectra < shortest)
          shortest = lives[i].damage.life_spectra, first = int(i);
      return first;
    }
  } // namespace

  GearboxResult analyse(const GearboxInput &in)
  {
    in.spectrum.check();
    scuffing::check(in.conditions, in.oil);
    if (in.materials.size() != in.stages.size())
      throw InputError("Materials", std::to_string(in.materials.size()) + " given",
                       std::to_string(in.stages.size()) + " (one per stage)");
    for (std::size_t k = 0; k < in.materials.size(); ++k)
      {
        const std::string p = in.stages[k].name + "/";
        fatigue::check_curve(in.materials[k].contact, p + "Contact");
        fatigue::check_curve(in.materials[k].bending, p + "Bending");
        geometry::limits::check_youngs_modulus(p + "Young's modulus", in.materials[k].E);
        require_range(p + "Poisson ratio", in.materials[k].nu, 0.0, 0.49);
        require_range(p + "Roughness Ra", in.materials[k].Ra * 1e6, 0.01, 1.0, "um");
      }
    GearboxResult r;
    r.train = build_train(in);
    r.stress = agma_stresses(r.train, in.spectrum, in.agma);
    r.scuff = scuffing_table(r.train, in.spectrum, in.agma, in.materials, in.oil, in.conditions);
    r.lives = member_lives(r.train, in.spectrum, r.stress, in.materials);
    r.first_failure = first_failure(r.lives);
    return r;
  }

  void use_reference_stresses(GearboxResult &r, const GearboxInput &in,
                              const std::vector<std::vector<MeshStress>> &at_ref, double M_ref)
  {
    use_stress_table(r, in, scaled_stresses(r.train, in.spectrum, at_ref, M_ref));
  }

  void use_stress_table(GearboxResult &r, const GearboxInput &in, StressTable s)
  {
    const std::string what = "stress table of the damage sum";
    if (s.size() != r.stress.size())
      throw InputError(what, std::to_string(s.size()) + " stages", std::to_string(r.stress.size()) + " stages");
    for (std::size_t k = 0; k < s.size(); ++k)
      {
        if (s[k].size() != r.stress[k].size())
          throw InputError(what + " of stage " + std::to_string(k + 1), std::to_string(s[k].size()) + " meshes",
                           std::to_string(r.stress[k].size()) + " meshes");
        for (std::size_t j = 0; j < s[k].size(); ++j)
          {
            if (s[k][j].size() != r.stress[k][j].size())
              throw InputError(what + " of stage " + std::to_string(k + 1), std::to_string(s[k][j].size()) + " bins",
                               std::to_string(r.stress[k][j].size()) + " bins");
            for (std::size_t b = 0; b < s[k][j].size(); ++b)
              {
                MeshStress &m = s[k][j][b];
                for (double v : {m.sigma_H, m.sigma_F1, m.sigma_F2})
                  if (!(std::isfinite(v) && v >= 0.0))
                    throw InputError(what + " of stage " + std::to_string(k + 1) + ", bin " + std::to_string(b + 1),
                                     to_string_g(v / 1e6) + " MPa", "finite and >= 0 MPa");
                const MeshStress &o = r.stress[k][j][b];
                m.sigma_H1_iso = o.sigma_H1_iso, m.sigma_H2_iso = o.sigma_H2_iso;
                m.sigma_F1_iso = o.sigma_F1_iso, m.sigma_F2_iso = o.sigma_F2_iso;
              }
          }
      }
    r.stress = std::move(s);
    r.lives = member_lives(r.train, in.spectrum, r.stress, in.materials);
    r.first_failure = first_failure(r.lives);
  }
} // namespace gearfem::gearbox
