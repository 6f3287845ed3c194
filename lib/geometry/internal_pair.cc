// InternalGearPair: placement and flank facts of a pinion meshing inside a ring.
#include "geometry/internal_pair.h"

#include "base/errors.h"
#include "base/units.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace gearfem::geometry
{
  namespace
  {

    InternalMeshInput mesh_input(const ToothProfile &pinion, const InternalToothProfile &ring, double a)
    {
      const auto &p = pinion.parameters();
      InternalMeshInput in;
      ring.fill_mesh_input(in);
      in.pinion_name = p.name;
      in.z1          = p.teeth;
      in.x1          = p.profile_shift;
      // The active flank ends where the tip rounding (or the tip) begins, as for GearPair.
      in.tip_radius1  = pinion.radii().tip_form;
      in.root_radius1 = pinion.radii().root;
      in.form_radius1 = pinion.radii().form;
      in.center_distance = a;
      const double mr = ring.parameters().module, mp = p.rack.module;
      if (std::abs(mr - mp) > 1e-12 * mp)
        throw InputError(ring.parameters().name + "/Module", mm_text(mr), "the pinion's module " + mm_text(mp));
      const double ar = ring.parameters().pressure_angle, ap = p.rack.pressure_angle;
      if (std::abs(ar - ap) > 1e-12)
        throw InputError(ring.parameters().name + "/Pressure angle", to_string_g(ar / units::deg) + " deg",
                         "the pinion's " + to_string_g(ap / units::deg) + " deg");
      return in;
    }
  } // namespace

  InternalGearPair::InternalGearPair(ToothProfile pinion, InternalToothProfile ring, double a, double ring_face_width)
    : pinion_(std::move(pinion))
    , ring_(std::move(ring))
    , mesh_(internal_mesh(mesh_input(pinion_, ring_, a)))
    , ring_width_(ring_face_width > 0 ? ring_face_width : pinion_.parameters().face_width)
  {
    for (const auto &d : interference_checks(mesh_))
      {
        if (!d.interferes)
          continue;
        if (d.name.find("radial") != std::string::npos || d.name.find("withdraw") != std::string::npos)
          warnings_.push_back(d.message() + " (the pinion must be assembled axially)");
        else
          d.raise();
      }
    if (mesh_.contact_ratio < 1.0)
      throw InputError(ring_.parameters().name + "/Tip diameter", mm_text(2 * mesh_.in.tip_radius2),
                       "a value giving a transverse contact ratio >= 1",
                       "contact ratio " + to_string_g(mesh_.contact_ratio) + " < 1");
    // The working-circle thicknesses of the outlines themselves (the pinion's includes its
    // thickness allowance), the backlash they leave and the phases that put both drive flanks
    // through C at phi1 = 0.
    const double sw1 = pinion_.thickness_at_radius(mesh_.rw1);
    const double sw2 = ring_.involute_thickness_at_radius(mesh_.rw2);
    jt_ = 2 * units::pi * mesh_.rw1 / teeth(1) - sw1 - sw2;
    if (std::abs(jt_) < 1e-13)
      jt_ = 0.0;
    if (jt_ < -1e-12)
      throw InputError("Pair/Centre distance", mm_text(mesh_.a), "a value with backlash >= 0",
                       "negative backlash: circumferential backlash " + to_string_g(jt_ / units::um) + " um");
    phase1_ = -sw1 / (2 * mesh_.rw1);
    phase2_ = sw2 / (2 * mesh_.rw2);
    for (const auto &w : ring_.warnings())
      warnings_.push_back(w);
  }

  int InternalGearPair::teeth(int i) const { return i == 1 ? pinion_.teeth() : ring_.parameters().teeth; }

  Placement InternalGearPair::placement(int i, double phi1) const
  {
    if (i == 1)
      return {Vec2::Zero(), phase1_ + phi1};
    return {Vec2(0.0, -mesh_.a), phase2_ + phi1 / ratio()};
  }

  Vec2 InternalGearPair::path_point(double phi1) const
  {
    return mesh_.position(point("C").g + mesh_.rb1 * phi1);
  }

  double InternalGearPair::flank_length_to_tip(int i, double r) const
  {
    if (i == 1)
      {
        const double rtf = pinion_.radii().tip_form;
        return std::max(0.0, (rtf * rtf - r * r) / (2 * mesh_.rb1));
      }
    const double ra = ring_.radii().tip;
    return std::max(0.0, (r * r - ra * ra) / (2 * mesh_.rb2));
  }

  bool InternalGearPair::beyond_tip_form(int i, double r, double tol) const
  {
    return i == 1 ? r >= pinion_.radii().tip_form - tol : r <= ring_.radii().tip + tol;
  }

  std::array<double, 2> InternalGearPair::radii_of_curvature(const Vec2 &x, const std::array<Placement, 2> &P) const
  {
    const double rb1 = mesh_.rb1, rb2 = mesh_.rb2;
    const double r1 = (x - P[0].centre).norm(), r2 = (x - P[1].centre).norm();
    return {r1 > rb1 ? std::sqrt(r1 * r1 - rb1 * rb1) : 0.0, r2 > rb2 ? -std::sqrt(r2 * r2 - rb2 * rb2) : 0.0};
  }

  bool InternalGearPair::has_relief(int i) const
  {
    return i == 1 && pinion_.parameters().relief.kind != TipRelief::Kind::none;
  }

  std::string geometry_fingerprint(const InternalGearPair &pair)
  {
    std::ostringstream s;
    s.precision(12);
    const auto &g = pair.pinion();
    const auto &p = g.parameters();
    s << g.teeth() << ' ' << p.rack.module << ' ' << p.rack.pressure_angle << ' ' << p.profile_shift << ' '
      << p.face_width << ' ' << g.radii().tip << ' ' << g.radii().root << ' ' << g.radii().base << ' '
      << g.tip_thickness() << ' ' << p.relief.amount << ' ' << p.rack.tip_radius << ';';
    const auto &r = pair.ring().parameters();
    const auto &k = pair.ring().radii();
    s << "internal " << r.teeth << ' ' << r.module << ' ' << r.pressure_angle << ' ' << r.profile_shift << ' '
      << pair.face_width(2) << ' ' << k.tip << ' ' << k.root << ' ' << k.base << ' ' << r.cutter.teeth << ' '
      << r.cutter.shift << ' ' << r.cutter.addendum << ' ' << r.cutter.tip_radius << ';' << pair.center_distance();
    return text_fingerprint(s.str());
  }
} // namespace gearfem::geometry
