// Gear body domains (full gear or sector) from a ToothProfile.
#include "base/errors.h"
#include "geometry/rim.h"
#include "base/units.h"
#include "base/number.h"
#include "base/roots.h"
#include "mesh/gear_mesh.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <sstream>
#include <utility>

namespace gearfem::mesh
{
  namespace
  {
    using units::pi;
  } // namespace

  double contact_size(const GearMeshParameters &p, double module)
  {
    return p.h_contact > 0 ? p.h_contact : module / 30.0;
  }

  double coast_size(const GearMeshParameters &p) { return p.h_coast > 0 ? p.h_coast : p.h_fillet; }

  double tooth_size(const GearMeshParameters &p, double module)
  {
    return p.h_tooth > 0 ? p.h_tooth : std::min(p.h_body, 0.4 * module);
  }

  double corner_size(const GearMeshParameters &p, double module)
  {
    const double h = contact_size(p, module);
    return p.h_corner > 0 ? std::min(p.h_corner, h) : 0.25 * h;
  }

  void GearMeshParameters::validate() const
  {
    if (model == Model::sector && sector_teeth < 1)
      throw InputError("Mesh/Sector teeth", std::to_string(sector_teeth), ">= 1");
    if (!(h_contact >= 0))
      throw InputError("Mesh/h_contact", to_string_g(h_contact * 1e3) + " mm", ">= 0 (0: m_n/30)");
    if (!(h_corner >= 0))
      throw InputError("Mesh/h_corner", to_string_g(h_corner * 1e3) + " mm", ">= 0 (0: h_contact/4)");
    if (!(h_coast >= 0) || h_coast > h_body)
      throw InputError("Mesh/h_coast", to_string_g(h_coast * 1e3) + " mm", "[0, h_body] (0: h_fillet)");
    require_greater("Mesh/h_fillet", h_fillet * 1e3, 0.0, "mm");
    require_greater("Mesh/h_body", h_body * 1e3, 0.0, "mm");
    if (h_contact > h_body)
      throw InputError("Mesh/h_contact", to_string_g(h_contact * 1e3) + " mm",
                       "<= h_body = " + to_string_g(h_body * 1e3) + " mm");
    if (h_fillet > h_body)
      throw InputError("Mesh/h_fillet", to_string_g(h_fillet * 1e3) + " mm",
                       "<= h_body = " + to_string_g(h_body * 1e3) + " mm");
    if (h_tooth < 0)
      throw InputError("Mesh/h_tooth", to_string_g(h_tooth * 1e3) + " mm", ">= 0 (0: automatic)");
    require_greater("Mesh/Growth ratio", growth, 1.0);
    if (bore_radius < 0)
      throw InputError("Mesh/Bore radius", to_string_g(bore_radius * 1e3) + " mm", ">= 0 (0: automatic)");
    if (rim_thickness < 0)
      throw InputError("Mesh/Rim thickness", to_string_g(rim_thickness * 1e3) + " mm",
                       ">= 0 (0: automatic)");
    if (fine_teeth != "auto" && fine_teeth != "loaded")
      {
        try
          {
            if (parse_int_list("Mesh/Fine teeth", fine_teeth).empty())
              throw InputError("Mesh/Fine teeth", fine_teeth, "auto, loaded or a list of tooth indices");
          }
        catch (const InputError &)
          {
            throw InputError("Mesh/Fine teeth", fine_teeth, "auto, loaded or a list of tooth indices");
          }
      }
  }

  std::vector<int> model_teeth(const GearMeshParameters &p, int z)
  {
    std::vector<int> t;
    if (p.model == GearMeshParameters::Model::full_gear)
      for (int k = 0; k < z; ++k)
        t.push_back(k);
    else
      {
        if (p.sector_teeth > z)
          throw InputError("Mesh/Sector teeth", std::to_string(p.sector_teeth),
                           "<= number of teeth " + std::to_string(z));
        const int first = -(p.sector_teeth - 1) / 2;
        for (int k = first; k < first + p.sector_teeth; ++k)
          t.push_back(k);
      }
    return t;
  }

  std::string fine_teeth_list(const std::vector<int> &teeth, int sign)
  {
    std::vector<int> t;
    for (const int k : teeth)
      t.push_back(sign * k);
    std::sort(t.begin(), t.end());
    std::string s;
    for (const int k : t)
      s += (s.empty() ? "" : ",") + std::to_string(k);
    return s;
  }

  std::vector<int> fine_teeth(const GearMeshParameters &p, int z)
  {
    if (p.fine_teeth == "loaded")
      throw InputError("Mesh/Fine teeth", "loaded",
                       "auto or a list of tooth indices here (loaded needs the Solve positions of gearfem solve)");
    std::set<int> s;
    if (p.fine_teeth == "auto")
      {
        if (p.model == GearMeshParameters::Model::sector)
          for (int k : model_teeth(p, z))
            s.insert(wrap_index(k, z));
        else
          for (int k = -2; k <= 2; ++k)
            s.insert(wrap_index(k, z));
      }
    else
      {
        for (const int k : parse_int_list("Mesh/Fine teeth", p.fine_teeth))
          s.insert(wrap_index(k, z));
      }
    return {s.begin(), s.end()};
  }

  double inner_radius(const GearMeshParameters &p, const geometry::ToothProfile &tooth)
  {
    const double rf = tooth.radii().root;
    const double ri = geometry::rim_inner_radius(tooth, p.bore_radius, p.rim_thickness,
                                                 p.model == GearMeshParameters::Model::sector);
    if (p.rim_thickness > 0 && !(ri > 0.05 * rf))
      throw InputError("Mesh/Rim thickness", to_string_g(p.rim_thickness * 1e3) + " mm",
                       "< 0.95 root radius = " + to_string_g(0.95 * rf * 1e3) + " mm", "the rim leaves no material");
    if (!(ri > 0 && ri < rf - std::min(p.h_fillet, 0.1 * rf)))
      throw InputError(p.rim_thickness > 0 ? "Mesh/Rim thickness" : "Mesh/Bore radius",
                       to_string_g((p.rim_thickness > 0 ? p.rim_thickness : ri) * 1e3) + " mm",
                       "bore radius in (0, root radius = " + to_string_g(rf * 1e3) + " mm)",
                       "no material left between the bore and the root circle");
    return ri;
  }

  namespace
  {
  double cell_estimate(const GearMeshParameters &p, const geometry::ToothProfile &tooth, double ri, double h_coarse,
                       int n_teeth, int n_fine)
  {
    const double m          = tooth.parameters().rack.module;
    const double tooth_area = 2.25 * m * units::pi * m / 2;
    const double h_fine     = std::min(contact_size(p, m), p.h_fillet);
    const double fraction   = double(n_teeth) / tooth.teeth();
    const double ring       = fraction * units::pi * (std::pow(tooth.radii().root, 2) - std::pow(ri, 2));
    return ring / (p.h_body * p.h_body) + n_fine * tooth_area / (h_fine * h_fine) +
           (n_teeth - n_fine) * tooth_area / (h_coarse * h_coarse);
  }

  /// Named stops for meshes that would not resolve the tooth or would not fit one machine.
  void check_resolution(const GearMeshParameters &p, const geometry::ToothProfile &tooth,
                        double ri, double h_coarse, int n_teeth, int n_fine)
  {
    // A fine tooth needs a few elements along its flank (the active flank is shorter than
    // the whole depth 2.25 m): with h_contact or h_fillet above the module, gmsh still
    // returns a mesh, but of degenerate cells (angles of 2 and 178 deg at m = 0.1 mm,
    // h = 0.5 mm) that do not represent the tooth.
    const double m = tooth.parameters().rack.module;
    const auto mm  = [](double x) { return to_string_g(x * 1e3) + " mm"; };
    if (p.h_contact > m)
      throw InputError("Mesh/h_contact", mm(p.h_contact), "<= module = " + mm(m),
                       "fewer than ~2 elements along the flank do not resolve the tooth");
    if (p.h_fillet > m)
      throw InputError("Mesh/h_fillet", mm(p.h_fillet), "<= module = " + mm(m),
                       "fewer than ~2 elements along the fillet do not resolve the tooth");
    if (p.h_tooth > m)
      throw InputError("Mesh/h_tooth", mm(p.h_tooth), "<= module = " + mm(m) + " (0: automatic)");
    // The limit keeps a mesh within the memory and time of one machine (a full gear of 10000
    // teeth at the default sizes would need ~1e8 cells): beyond it, stop with the estimate
    // instead of meshing for hours.
    const double limit    = max_cells;
    const double estimate = cell_estimate(p, tooth, ri, h_coarse, n_teeth, n_fine);
    if (!(estimate <= limit))
      throw InputError(p.model == GearMeshParameters::Model::full_gear ? "Mesh/Model" : "Mesh/h_body",
                       p.model == GearMeshParameters::Model::full_gear ?
                         "full gear (" + std::to_string(tooth.teeth()) + " teeth)" :
                         mm(p.h_body),
                       "a mesh of <= 2e6 cells (estimated: " + to_string_g(estimate) + ")",
                       "use Model = sector, or larger h_body/h_tooth");
  }

  /// A sharp tip corner of a tooth outline: where the flank of one side meets the tip land
  /// without a tip rounding. For each of the two segments, the parameter at chord distance
  /// `length` from the corner (the chord grows monotonically along a short flank or tip
  /// arc) and the parameter of the corner end.
  struct CornerZone
  {
    int segment[2] = {-1, -1};
    double t_cut[2] = {0, 0}, t_corner[2] = {0, 0};
    bool contains(int s, double t) const
    {
      for (int i = 0; i < 2; ++i)
        if (segment[i] == s)
          return (t - t_cut[i]) * (t - t_corner[i]) <= 0;
      return false;
    }
  };
  CornerZone tip_corner(const std::vector<geometry::ProfileSegment> &segs, geometry::Side side, double length)
  {
    using geometry::SegmentType;
    CornerZone z;
    int tip = -1;
    for (std::size_t s = 0; s < segs.size(); ++s)
      if (segs[s].type == SegmentType::tip)
        tip = int(s);
    for (int flank = 0; flank < int(segs.size()) && tip >= 0; ++flank)
    {
    if (segs[flank].type != SegmentType::flank || segs[flank].side != side)
      continue;
    const auto &f = segs[flank], &t = segs[tip];
    const double tol = 1e-9 * f.curve->point(f.t1).norm();
    for (const double tf : {f.t0, f.t1})
      for (const double tt : {t.t0, t.t1})
        if ((f.curve->point(tf) - t.curve->point(tt)).norm() < tol)
          {
            const Vec2 corner = f.curve->point(tf);
            const std::pair<int, double> ends[2] = {{flank, tf}, {tip, tt}};
            for (int i = 0; i < 2; ++i)
              {
                const auto &sg  = segs[ends[i].first];
                const double te = ends[i].second, to = te == sg.t0 ? sg.t1 : sg.t0;
                if ((sg.curve->point(to) - corner).norm() <= length)
                  return CornerZone(); // the segment is shorter than the zone: no grading
                const double t_cut = base::find_root_bisection(
                  [&](double x) { return (sg.curve->point(x) - corner).norm() - length; }, te, to,
                  "tip-corner zone: chord from the corner");
                z.segment[i] = ends[i].first, z.t_cut[i] = t_cut, z.t_corner[i] = te;
              }
            return z;
          }
    }
    return z;
  }
  } // namespace

  double max_tooth_angle_step(const geometry::ToothProfile &tooth)
  {
    const auto &segs = tooth.segments();
    if (segs.size() < 2 || segs.front().type != geometry::SegmentType::root ||
        segs.back().type != geometry::SegmentType::root)
      return 0;
    double w = std::numeric_limits<double>::infinity();
    for (const auto *sg : {&segs.front(), &segs.back()})
      {
        const Vec2 a = sg->start(), b = sg->end(), c = sg->point(0.5);
        const double r = a.norm();
        if (std::abs(b.norm() - r) > 1e-9 * r || std::abs(c.norm() - r) > 1e-9 * r)
          return 0; // not an arc of a circle about the gear centre
        w = std::min(w, std::abs(std::remainder(std::atan2(b.y(), b.x()) - std::atan2(a.y(), a.x()), 2 * pi)));
      }
    return w;
  }

  void check_tooth_angles(const geometry::ToothProfile &tooth, const std::vector<double> &angles,
                          const std::string &entry)
  {
    if (angles.empty())
      return;
    const int z = tooth.teeth();
    if (int(angles.size()) != z)
      throw InputError(entry, std::to_string(angles.size()) + " values", std::to_string(z) + " values (one per tooth)");
    for (int k = 0; k < z; ++k)
      if (!std::isfinite(angles[std::size_t(k)]))
        throw InputError(entry, "tooth " + std::to_string(k) + ": " + to_string_g(angles[std::size_t(k)]),
                         "finite angles [rad]");
    const double w = max_tooth_angle_step(tooth);
    for (int k = 0; k < z; ++k)
      {
        const double step = angles[std::size_t(k)] - angles[std::size_t(wrap_index(k - 1, z))];
        if (w == 0 && step != 0)
          throw InputError(entry, "tooth " + std::to_string(k) + " turned " + to_string_g(step * 1e6) +
                                    " urad against tooth " + std::to_string(wrap_index(k - 1, z)),
                           "equal offsets on every tooth",
                           "the outline has no root land arc: the fillets of neighbouring teeth meet at a "
                           "point, where turned teeth would overlap or leave a gap");
        if (std::abs(step) > w)
          throw InputError(entry, "tooth " + std::to_string(k) + " turned " + to_string_g(step * 1e6) +
                                    " urad against tooth " + std::to_string(wrap_index(k - 1, z)),
                           "within +-" + to_string_g(w * 1e6) + " urad (half a root land)",
                           "neighbouring teeth meet on their root lands, which keep at least half their length");
      }
  }

  namespace
  {
    /// A half root land of a placed tooth (the first or last piece of its outline, an arc of the
    /// root circle) as an arc of that circle parametrised by the polar angle, with its free end
    /// (the start when `first`, else the end) moved by `shift` [rad] along the circle.
    void root_land_arc(BoundaryPiece &piece, bool first, double shift)
    {
      const Vec2 a = piece.start(), b = piece.end();
      const double ta = std::atan2(a.y(), a.x());
      const double tb = ta + std::remainder(std::atan2(b.y(), b.x()) - ta, 2 * pi);
      piece.curve     = ParametricCurve::circle(Vec2(0, 0), a.norm());
      piece.t0        = first ? ta + shift : ta;
      piece.t1        = first ? tb : tb + shift;
    }
  } // namespace

  boundary::Code segment_code(geometry::SegmentType type, geometry::Side side)
  {
    using geometry::SegmentType;
    const bool drive = side == geometry::Side::drive;
    switch (type)
      {
        case SegmentType::flank:
          return drive ? boundary::flank_drive : boundary::flank_coast;
        case SegmentType::fillet:
          return drive ? boundary::fillet_drive : boundary::fillet_coast;
        case SegmentType::root:
          return drive ? boundary::root_drive : boundary::root_coast;
        case SegmentType::tip_rounding:
          return drive ? boundary::tip_round_drive : boundary::tip_round_coast;
        case SegmentType::tip:
          break;
      }
    return boundary::tip;
  }

  namespace
  {
  /// The outline `outer` closed into the domain: a full gear's outline with the bore as a hole,
  /// a sector's with its radial cut edges and the inner arc.
  void close_domain(Domain &d, Loop outer, const GearMeshParameters &p, double ri)
  {
    const Vec2 start = outer.pieces.front().start(), end = outer.pieces.back().end();
    if (p.model == GearMeshParameters::Model::full_gear)
      {
        // Close the outline exactly (tooth z-1 ends where tooth 0 starts).
        if ((start - end).norm() > 1e-9 * start.norm())
          throw InputError("Gear outline", "not closed (gap " + to_string_g((start - end).norm()) + " m)",
                           "a closed outline");
        d.loops.push_back(outer);
        Loop hole;
        for (int q = 0; q < 4; ++q)
          {
            BoundaryPiece b;
            b.curve       = ParametricCurve::circle(Vec2(0, 0), ri);
            b.t0          = -q * pi / 2;
            b.t1          = -(q + 1) * pi / 2;
            b.boundary_id = boundary::bore;
            b.size        = p.h_body;
            hole.pieces.push_back(b);
          }
        d.loops.push_back(hole);
      }
    else
      {
        const Vec2 end_in = ri * end.normalized(), start_in = ri * start.normalized();
        BoundaryPiece cut_ccw;
        cut_ccw.curve       = ParametricCurve::line(end, end_in);
        cut_ccw.straight    = true;
        cut_ccw.boundary_id = boundary::cut_ccw;
        outer.pieces.push_back(cut_ccw);
        const double a_end = std::atan2(end_in.y(), end_in.x());
        double a_start     = std::atan2(start_in.y(), start_in.x());
        while (a_start > a_end)
          a_start -= 2 * pi;
        // Inner arc from the ccw end back to the cw start (clockwise), in pieces <= 90 deg.
        const int n_arc = std::max(1, int(std::ceil((a_end - a_start) / (pi / 2))));
        for (int q = 0; q < n_arc; ++q)
          {
            BoundaryPiece b;
            b.curve       = ParametricCurve::circle(Vec2(0, 0), ri);
            b.t0          = a_end - (a_end - a_start) * q / n_arc;
            b.t1          = a_end - (a_end - a_start) * (q + 1) / n_arc;
            b.boundary_id = boundary::bore;
            b.size        = p.h_body;
            outer.pieces.push_back(b);
          }
        BoundaryPiece cut_cw;
        cut_cw.curve       = ParametricCurve::line(start_in, start);
        cut_cw.straight    = true;
        cut_cw.boundary_id = boundary::cut_cw;
        outer.pieces.push_back(cut_cw);
        d.loops.push_back(outer);
      }
  }
  } // namespace

  Domain gear_domain(const geometry::ToothProfile &tooth, const GearMeshParameters &p)
  {
    p.validate();
    const int z                 = tooth.teeth();
    const double m              = tooth.parameters().rack.module;
    const double ri             = inner_radius(p, tooth);
    const std::vector<int> fine = fine_teeth(p, z);
    const std::set<int> fine_set(fine.begin(), fine.end());
    const double h_coarse = tooth_size(p, m);
    // A corner grading finer than h_contact/50 adds thousands of elements per corner and
    // hangs gmsh's size-field meshing (0.5 nm under 0.5 mm ran past any time limit).
    if (p.h_corner > 0 && p.h_corner < contact_size(p, m) / 50)
      throw InputError("Mesh/h_corner", to_string_g(p.h_corner * 1e3) + " mm",
                       "0 (h_contact/4) or >= h_contact/50 = " + to_string_g(contact_size(p, m) / 50 * 1e3) + " mm");
    check_resolution(p, tooth, ri, h_coarse, int(model_teeth(p, z).size()), int(fine.size()));

    Domain d;
    d.h_body = p.h_body;
    d.growth = p.growth;
    Loop outer;
    const auto &segs = tooth.segments();
    // A sharp drive tip corner gets h_corner over the last 2 h_contact of flank and tip land.
    const double h_corner = corner_size(p, m);
    const CornerZone corner = h_corner < contact_size(p, m) ?
                                tip_corner(segs, geometry::Side::drive, 2 * contact_size(p, m)) :
                                CornerZone();
    // A sharp coast tip corner where the coast flank is more than 2x coarser than the tip
    // land: the last 2 h_coast of the coast flank take the geometric mean of the two sizes.
    // Without it gmsh's Blossom recombination leaves triangle pairs at that corner (Parker
    // gear, h_contact 0.075 mm, h_coast 0.25 mm) and the mesher falls back to subdivision.
    const double h_coast_flank = coast_size(p), h_tip_land = contact_size(p, m);
    const double h_coast_corner = std::sqrt(h_coast_flank * h_tip_land);
    CornerZone coast_corner;
    if (h_coast_flank > coast_jump_limit * h_tip_land)
      {
        coast_corner            = tip_corner(segs, geometry::Side::coast, 2 * h_coast_flank);
        coast_corner.segment[1] = -1; // the tip land keeps h_contact
      }
    // Tooth placement offsets: tooth k turned by delta_k; the root lands of teeth k - 1 and k
    // meet at the mean of their offsets (the ends of a sector keep their own).
    check_tooth_angles(tooth, p.tooth_angles, "tooth placement offsets of the " + std::to_string(z) + "-tooth gear");
    const bool turned = !p.tooth_angles.empty() && max_tooth_angle_step(tooth) > 0;
    const std::vector<int> teeth = model_teeth(p, z);
    const auto delta = [&](int k) { return p.tooth_angles.empty() ? 0.0 : p.tooth_angles[std::size_t(wrap_index(k, z))]; };
    for (const int k : teeth)
      {
        const double angle = 2.0 * pi * k / z + delta(k);
        const bool is_fine = fine_set.count(wrap_index(k, z)) > 0;
        for (std::size_t s = 0; s < segs.size(); ++s)
          {
            const auto &sg = segs[s];
            BoundaryPiece piece;
            piece.curve       = ParametricCurve::from(sg.curve, angle);
            piece.t0          = sg.t0;
            piece.t1          = sg.t1;
            const auto code   = segment_code(sg.type, sg.side);
            piece.boundary_id = boundary::tooth_id(wrap_index(k, z), code);
            piece.tooth       = wrap_index(k, z);
            piece.segment     = int(s);
            if (turned && (s == 0 || s + 1 == segs.size()))
              {
                const bool full = p.model == GearMeshParameters::Model::full_gear;
                const int next  = s == 0 ? k - 1 : k + 1;
                const bool end  = next < teeth.front() || next > teeth.back();
                root_land_arc(piece, s == 0, full || !end ? 0.5 * (delta(next) - delta(k)) : 0.0);
              }
            // The fillet of a closed rack's tooth carries contact (geometry::GeneratingRack::closed).
            const bool contact_fillet = sg.type == geometry::SegmentType::fillet && tooth.rack().closed();
            const bool flank_like = sg.type == geometry::SegmentType::flank ||
                                    sg.type == geometry::SegmentType::tip ||
                                    sg.type == geometry::SegmentType::tip_rounding || contact_fillet;
            const bool coast = sg.side == geometry::Side::coast &&
                               (sg.type == geometry::SegmentType::flank ||
                                sg.type == geometry::SegmentType::tip_rounding || contact_fillet);
            const double h_flank = coast ? coast_size(p) : contact_size(p, m);
            piece.size = !is_fine ? h_coarse : (flank_like ? h_flank : p.h_fillet);
            // Split fine flanks at the requested radii (those inside the piece).
            std::vector<double> cuts;
            for (int i = 0; i < 2; ++i)
              for (const CornerZone *zone : {&corner, static_cast<const CornerZone *>(&coast_corner)})
                if (is_fine && zone->segment[i] == int(s))
                  cuts.push_back(zone->t_cut[i]);
            if (is_fine && sg.type == geometry::SegmentType::flank)
              for (const double r : p.flank_split_radii)
                {
                  const double ra = sg.curve->point(sg.t0).norm(), rb = sg.curve->point(sg.t1).norm();
                  if (!(r > std::min(ra, rb) + 1e-3 * contact_size(p, m) && r < std::max(ra, rb) - 1e-3 * contact_size(p, m)))
                    continue;
                  cuts.push_back(geometry::parameter_at_radius(*sg.curve, sg.t0, sg.t1, r));
                }
            std::sort(cuts.begin(), cuts.end(), [&](double x, double y) {
              return (sg.t1 >= sg.t0) ? x < y : x > y;
            });
            double t_prev = piece.t0;
            for (const double c : cuts)
              {
                BoundaryPiece first = piece;
                first.t0            = t_prev;
                first.t1            = c;
                if (is_fine && corner.contains(int(s), 0.5 * (first.t0 + first.t1)))
                  first.size = h_corner;
                if (is_fine && coast_corner.contains(int(s), 0.5 * (first.t0 + first.t1)))
                  first.size = h_coast_corner;
                outer.pieces.push_back(first);
                t_prev = c;
              }
            piece.t0 = t_prev;
            if (is_fine && corner.contains(int(s), 0.5 * (piece.t0 + piece.t1)))
              piece.size = h_corner;
            if (is_fine && coast_corner.contains(int(s), 0.5 * (piece.t0 + piece.t1)))
              piece.size = h_coast_corner;
            outer.pieces.push_back(piece);
          }
      }
    close_domain(d, std::move(outer), p, ri);
    return d;
  }

  double estimated_cells(const GearMeshParameters &p, const geometry::ToothProfile &tooth)
  {
    const int z = tooth.teeth();
    return cell_estimate(p, tooth, inner_radius(p, tooth), tooth_size(p, tooth.parameters().rack.module),
                         int(model_teeth(p, z).size()), int(fine_teeth(p, z).size()));
  }

  MeshData mesh_gear(const geometry::ToothProfile &tooth, const GearMeshParameters &p,
                     const std::filesystem::path &msh_file)
  {
    MeshingOptions o;
    o.msh_file          = msh_file;
    o.samples_per_piece = p.spline_samples;
    o.model_name        = "gear_z" + std::to_string(tooth.teeth());
    o.fallbacks         = p.quad_fallbacks;
    if (p.tiled) // mesh_gear_tiled refuses what it does not serve
      {
        MeshData m = mesh_gear_tiled(tooth, p, o);
        if (!m.cells.empty())
          {
            if (!msh_file.empty())
              write_mesh_msh(m, msh_file, o.model_name);
            return m;
          }
      }
    return mesh_domain(gear_domain(tooth, p), o);
  }
} // namespace gearfem::mesh
