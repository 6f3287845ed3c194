#include "model_choice/choose.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace gearfem::model_choice
{
  namespace
  {
    std::string mm_3_text(double v)
    {
      std::ostringstream o;
      o.precision(3);
      o << v * 1e3 << " mm";
      return o.str();
    }

    std::string g3(double v)
    {
      std::ostringstream o;
      o.precision(3);
      o << v;
      return o.str();
    }

    std::string pc(double v)
    {
      std::ostringstream o;
      o.precision(3);
      o << v * 100 << " %";
      return o.str();
    }
  } // namespace

  const std::vector<int> &contact_rungs()
  {
    static const std::vector<int> n = {8, 10, 15, 20, 30, 45, 60, 90};
    return n;
  }

  double predicted_error(Quantity q, double h, double m, double a)
  {
    switch (q)
      {
        case Quantity::mean_ste:
          return 0.0194 * std::pow(h / (m / 10), 2);
        case Quantity::pp_ste:
          return h > m / 20 * (1 + 1e-9) ?
                   1.0 :
                   std::max(0.013 * std::pow(h / (m / 30), 2), a > 0 ? pp_per_half_width * std::pow(h / a, 2) : 0.0);
        case Quantity::p_max:
          return 0.081 * std::pow(h / (m / 30), 2);
        default:
          return 0;
      }
  }

  namespace
  {
    constexpr double resolution_m6 = 0.0182; ///< fillet_resolution at h_fillet m/6
  } // namespace

  double fillet_resolution(double h_fillet, double m)
  {
    return resolution_m6 * std::pow(6 * h_fillet / m, fillet_resolution_order);
  }

  double fillet_size_for_resolution(double resolution, double m)
  {
    return m / 6 * std::pow(resolution / resolution_m6, 1 / fillet_resolution_order);
  }

  double contact_half_width(const geometry::GearPair &pair, const analytical::PlaneElastic &e1,
                            const analytical::PlaneElastic &e2, double torque)
  {
    const double curvature = pair.equivalent_curvature(0);
    const double b         = std::min(pair.face_width(1), pair.face_width(2));
    const double rb        = pair.base_radius(1);
    if (!(torque > 0) || !(curvature > 0) || !(b > 0) || !(rb > 0) || !std::isfinite(curvature))
      return 0;
    // Both radii at C in one: R1 = R2 = 2 R gives R1 R2 / (R1 + R2) = R.
    const double a = analytical::hertz_line_contact(torque / (rb * b), 2 / curvature, 2 / curvature, e1, e2).half_width;
    return std::isfinite(a) && a > 0 ? a : 0; // 0: not known, the module's rung alone
  }

  double snap_finer(double h, double m)
  {
    for (const int n : contact_rungs())
      if (m / n <= 1.1 * h * (1 + 1e-9))
        return m / n;
    return h;
  }

  double body_size(double given, double m, double ring)
  {
    return std::max(given, std::min(1.5 * m, ring / 6));
  }

  double unloaded_tooth_size(double h_body, double m)
  {
    return std::min(h_body, 0.8 * m);
  }

  double flank_height_bound(const geometry::GearPair &pair)
  {
    double bound = 0;
    for (int i = 1; i <= 2; ++i)
      {
        const double r_sap  = i == 1 ? pair.point("A").r1 : pair.point("E").r2;
        const double r_form = pair.gear(i).radii().form;
        if (r_form > 0 && r_sap > r_form)
          bound = bound > 0 ? std::min(bound, r_sap - r_form) : r_sap - r_form;
      }
    return bound;
  }

  ModelChoice choose_model(const geometry::GearPair &pair, const mesh::GearMeshParameters given[2],
                           unsigned int degree, const AccuracyTarget &target, const FixedSettings &fixed,
                           double half_width)
  {
    ModelChoice c;
    c.mesh[0] = given[0];
    c.mesh[1] = given[1];
    c.degree  = degree;
    c.flank_height = flank_height_bound(pair);
    const double m = pair.gear(1).parameters().rack.module;
    auto &why      = c.reasons;

    // h_contact: the coarsest rung of the ladder whose predicted errors are all within 1.1 times
    // the tolerances (the estimate on the run then decides).
    const bool stress_asked = target.asks(Quantity::root_stress) || target.asks(Quantity::p_max);
    std::string driver;
    const auto rungs = contact_rungs();
    const bool contact_asked =
      target.asks(Quantity::mean_ste) || target.asks(Quantity::pp_ste) || target.asks(Quantity::p_max);
    // The coarsest rung whose predicted errors (with the half-width `a`; 0: the module alone)
    // are within 1.1 times the tolerances.
    auto coarsest = [&](double a) {
      if (!contact_asked)
        return m / 15;
      for (const int n : rungs)
        {
          bool ok = true;
          for (int q : {0, 1, 3})
            if (target.tolerance[q] > 0)
              ok = ok && predicted_error(static_cast<Quantity>(q), m / n, m, a) <= 1.1 * target.tolerance[q];
          if (ok)
            return m / n;
        }
      return m / rungs.back();
    };
    double h             = coarsest(half_width);
    c.ladder_h_contact   = coarsest(0);
    if (!contact_asked)
      driver = "no STE or pressure tolerance: m/15 keeps the mean STE within about 1 %";
    else
      {
        driver = "the coarsest rung m/" + std::to_string(int(std::lround(m / h))) +
                 " of the ladder whose predicted errors are within 1.1 times the tolerances:";
        for (int q : {0, 1, 3})
          if (target.tolerance[q] > 0)
            driver += std::string(" ") + AccuracyTarget::names()[q] + " " +
                      pc(predicted_error(static_cast<Quantity>(q), h, m, half_width));
        driver += " (order 2 from the worst measured: mean STE 1.94 % at m/10, p-p 1.3 % at m/30 (an envelope of the run's own "
                  "estimate with the swept ripple) and not coarser than m/20, where the tip-corner contact is unresolved, p_max 8.1 % at m/30)";
        if (h < c.ladder_h_contact * (1 - 1e-9))
          driver += "; finer than the module alone asks (m/" + std::to_string(int(std::lround(m / c.ladder_h_contact))) +
                    ") for the light load: the p-p estimate is also taken as " + pc(pp_per_half_width) +
                    " (h / a)^2, with the Hertz half-width a = " +
                    mm_3_text(half_width) + " at the lowest torque (h / a = " + g3(h / half_width) +
                    "; 2 a / h elements across the contact patch), and the companion is the module rung's";
      }
    const bool fillet_matters = stress_asked;
    if (fillet_matters && c.flank_height > 0 && h > c.flank_height)
      {
        h = c.flank_height;
        c.ladder_h_contact = std::min(c.ladder_h_contact, h);
        driver = "the flank height " + mm_3_text(c.flank_height) +
                 " between the start of active profile and the form circle: a coarser contact element lets the "
                 "contact of the tooth entering mesh leak into its fillet (Siasos 2010 23/69: root stress 25-36 % "
                 "off at h_contact 0.25-0.4 mm)";
      }
    for (auto &g : c.mesh)
      if (!fixed.h_contact)
        g.h_contact = h;
      else
        g.h_contact = mesh::contact_size(g, m);
    if (fixed.h_contact)
      why.push_back("h_contact " + mm_3_text(c.mesh[0].h_contact) + ": set in the input (Mesh/h_contact)");
    else
      why.push_back("h_contact " + mm_3_text(h) + " (m/" + std::to_string(int(std::lround(m / h))) + "): " + driver);

    // h_fillet: the root stress tolerance, else coarse.
    double hf = m / 8;
    std::string fdriver = "no root-stress tolerance: m/8";
    if (target.asks(Quantity::root_stress))
      {
        // The size whose resolution is within the tolerance / 1.1.
        hf = std::min(m / 12, fillet_size_for_resolution(target[Quantity::root_stress] / 1.1, m));
        fdriver = "root stress " + pc(target[Quantity::root_stress]) + " (resolution " +
                  pc(fillet_resolution(hf, m)) +
                  " there, the envelope of the measured errors; never coarser than m/12, so the fillet keeps "
                  "at least four elements)";
      }
    for (auto &g : c.mesh)
      if (!fixed.h_fillet)
        g.h_fillet = std::min(hf, g.h_body);
    why.push_back("h_fillet " + mm_3_text(c.mesh[0].h_fillet) + ": " +
                  (fixed.h_fillet ? std::string("set in the input (Mesh/h_fillet)") : fdriver));
    if (!fixed.h_corner)
      for (auto &g : c.mesh)
        g.h_corner = 0; // h_contact/4: the corner grading follows
    // Degree.
    const bool loose_ste = (!target.asks(Quantity::mean_ste) || target[Quantity::mean_ste] >= 0.03) &&
                           (!target.asks(Quantity::pp_ste) || target[Quantity::pp_ste] >= 0.05);
    if (!fixed.degree)
      {
        c.degree = fillet_matters || !loose_ste ? 2 : 1;
        why.push_back(c.degree == 2 ? "Q2: Q1 misses the mean STE by 1.9 %, the p-p by 3.5 %, the root stress by "
                                      "1.9 % and p_max by 31 % at m/30" :
                                      "Q1: a mean STE tolerance of 3 % or looser, a p-p one of 5 % or looser, no "
                                      "stress tolerance; Q1 costs a third of Q2 (mean STE 1.9 %, p-p 3.5 % at m/30)");
      }
    else
      why.push_back("degree " + std::to_string(c.degree) + ": set in the input (Finite elements/Degree)");
    if (!fixed.model)
      why.push_back(c.mesh[0].model == mesh::GearMeshParameters::Model::full_gear ?
                      "full gears: sectors are 20-36 % stiff on the mean STE and save at most a fifth of the cost" :
                      "sector: as the input");
    // The body and the unloaded teeth: sized for the target, not for every question.
    bool body_sized = false;
    for (int i = 0; i < 2; ++i)
      {
        auto &g = c.mesh[i];
        if (g.model != mesh::GearMeshParameters::Model::full_gear)
          continue;
        const auto &tooth = pair.gear(i + 1);
        const double mi   = tooth.parameters().rack.module;
        const double ring = tooth.radii().root - mesh::inner_radius(g, tooth);
        if (!fixed.h_body)
          g.h_body = body_size(g.h_body, mi, ring);
        if (!fixed.h_tooth)
          g.h_tooth = unloaded_tooth_size(g.h_body, mi);
        body_sized = body_sized || !fixed.h_body || !fixed.h_tooth;
      }
    if (body_sized)
      why.push_back("h_body " + mm_3_text(c.mesh[0].h_body) + " / " + mm_3_text(c.mesh[1].h_body) + ", h_tooth " +
                    mm_3_text(mesh::tooth_size(c.mesh[0], m)) + " / " +
                    mm_3_text(mesh::tooth_size(c.mesh[1], pair.gear(2).parameters().rack.module)) +
                    " (pinion / gear; unless set in the input): the body and the unloaded teeth carry no "
                    "contact and no fillet peak; 1.5 m (at least six elements through the ring) and 0.8 m instead of "
                    "3 mm and 0.4 m moved the true errors of five pairs by at most 0.009 % (mean STE), 0.014 % (p-p) "
                    "and 0.005 % (root stress), for 4-33 % fewer DoFs (validation/model_choice)");
    for (const auto &g : c.mesh)
      g.validate();
    return c;
  }
} // namespace gearfem::model_choice
