// Ring (internal gear) body domains, full ring or sector, from an InternalToothProfile.
#include "mesh/ring_domain.h"

#include "base/errors.h"
#include "base/number.h"
#include "base/roots.h"
#include "base/units.h"
#include "mesh/gear_mesh.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>

namespace gearfem::mesh
{
  namespace
  {
    using units::pi;
    /// Largest cell count of one ring mesh (the limit of gear_domain: one machine's memory).
    constexpr double max_cells = 2e6;

    double contact_size(const RingMeshParameters &p, double m) { return p.h_contact > 0 ? p.h_contact : m / 30.0; }
    double coast_size(const RingMeshParameters &p) { return p.h_coast > 0 ? p.h_coast : p.h_fillet; }
    double corner_size(const RingMeshParameters &p, double m)
    {
      const double h = contact_size(p, m);
      return p.h_corner > 0 ? std::min(p.h_corner, h) : 0.25 * h;
    }
    double tooth_size(const RingMeshParameters &p, double m)
    {
      return p.h_tooth > 0 ? p.h_tooth : std::min(p.h_body, 0.4 * m);
    }
  } // namespace

  double ring_contact_size(const RingMeshParameters &p, double module) { return contact_size(p, module); }

  void RingMeshParameters::validate() const
  {
    if (model == Model::sector && sector_teeth < 1)
      throw InputError("Mesh/Ring/Sector teeth", std::to_string(sector_teeth), ">= 1");
    require_greater("Mesh/Ring/h_body", h_body * 1e3, 0.0, "mm");
    require_greater("Mesh/Ring/h_fillet", h_fillet * 1e3, 0.0, "mm");
    require_greater("Mesh/Ring/Growth ratio", growth, 1.0);
    const std::pair<const char *, double> sizes[] = {
      {"Mesh/Ring/h_contact", h_contact}, {"Mesh/Ring/h_fillet", h_fillet}, {"Mesh/Ring/h_coast", h_coast},
      {"Mesh/Ring/h_corner", h_corner},   {"Mesh/Ring/h_tooth", h_tooth}};
    for (const auto &[entry, h] : sizes)
      if (!(h >= 0 && h <= h_body))
        throw InputError(entry, mm_text(h), "[0, h_body = " + mm_text(h_body) + "] (0: automatic where allowed)");
    if (!(rim_thickness >= 0))
      throw InputError("Mesh/Ring/Rim thickness", mm_text(rim_thickness), ">= 0 (0: from the backup ratio)");
    if (!(backup_ratio >= 0))
      throw InputError("Mesh/Ring/Backup ratio", to_string_g(backup_ratio), ">= 0 (0: 1.2)");
    if (rim_thickness > 0 && backup_ratio > 0)
      throw InputError("Mesh/Ring/Backup ratio", to_string_g(backup_ratio),
                       "0 when Mesh/Ring/Rim thickness is given (" + mm_text(rim_thickness) + ")",
                       "give the rim either as a thickness or as a backup ratio");
    if (bolts < 0)
      throw InputError("Mesh/Ring/Bolts", std::to_string(bolts), ">= 0 (0: outer circle clamped all round)");
    if (!std::isfinite(bolt_phase))
      throw InputError("Mesh/Ring/Bolt phase", to_string_g(bolt_phase), "a finite angle");
    if (!(bolt_width >= 0))
      throw InputError("Mesh/Ring/Bolt width", mm_text(bolt_width), ">= 0 (0: a tenth of the bolt spacing)");
    if (spline_samples < 2)
      throw InputError("Mesh/Ring/Spline samples", std::to_string(spline_samples), ">= 2");
    if (fine_teeth != "auto")
      {
        bool ok = true;
        try
          {
            ok = !parse_int_list("Mesh/Ring/Fine teeth", fine_teeth).empty();
          }
        catch (const InputError &)
          {
            ok = false;
          }
        if (!ok)
          throw InputError("Mesh/Ring/Fine teeth", fine_teeth, "auto or a list of tooth indices");
      }
  }

  double ring_rim_thickness(const geometry::InternalToothProfile &ring, const RingMeshParameters &p)
  {
    if (p.rim_thickness > 0)
      return p.rim_thickness;
    const double h_t = ring.radii().root - ring.radii().tip;
    return (p.backup_ratio > 0 ? p.backup_ratio : 1.2) * h_t;
  }

  double ring_outer_radius(const geometry::InternalToothProfile &ring, const RingMeshParameters &p)
  {
    return ring.radii().root + ring_rim_thickness(ring, p);
  }

  std::vector<int> ring_model_teeth(const RingMeshParameters &p, int z)
  {
    std::vector<int> t;
    if (p.model == RingMeshParameters::Model::full_ring)
      for (int k = 0; k < z; ++k)
        t.push_back(k);
    else
      {
        if (p.sector_teeth > z)
          throw InputError("Mesh/Ring/Sector teeth", std::to_string(p.sector_teeth),
                           "<= number of teeth " + std::to_string(z));
        const int first = -(p.sector_teeth - 1) / 2;
        for (int k = first; k < first + p.sector_teeth; ++k)
          t.push_back(k);
      }
    return t;
  }

  std::vector<int> ring_fine_teeth(const RingMeshParameters &p, int z)
  {
    std::set<int> s;
    if (p.fine_teeth != "auto")
      for (const int k : parse_int_list("Mesh/Ring/Fine teeth", p.fine_teeth))
        s.insert(wrap_index(k, z));
    else if (p.model == RingMeshParameters::Model::sector)
      for (const int k : ring_model_teeth(p, z))
        s.insert(wrap_index(k, z));
    else
      for (int k = -2; k <= 2; ++k)
        s.insert(wrap_index(k, z));
    return {s.begin(), s.end()};
  }

  namespace
  {
    /// Polar angle range [a_begin, a_end] of the model's outer circle (from +x, ccw) [rad].
    std::pair<double, double> outer_range(const geometry::InternalToothProfile &ring, const RingMeshParameters &p)
    {
      const int z = ring.parameters().teeth;
      if (p.model == RingMeshParameters::Model::full_ring)
        {
          // Start in the middle between bolt n - 1 and bolt 0, so that no support arc is cut.
          const double a = p.bolts > 0 ? 0.5 * pi + p.bolt_phase - pi / p.bolts : 0.0;
          return {a, a + 2 * pi};
        }
      const int first = ring_model_teeth(p, z).front();
      const Vec2 s    = ring.segments().front().start();
      const double a  = std::atan2(s.y(), s.x()) + 2 * pi * first / z;
      return {a, a + 2 * pi * p.sector_teeth / z};
    }

    /// Half angle of a support arc [rad], checked against the bolt spacing.
    double bolt_half_angle(const RingMeshParameters &p, double R)
    {
      const double spacing = 2 * pi * R / p.bolts;
      const double width   = p.bolt_width > 0 ? p.bolt_width : 0.1 * spacing;
      if (!(width < 0.5 * spacing))
        throw InputError("Mesh/Ring/Bolt width", mm_text(width), "< half the bolt spacing = " + mm_text(0.5 * spacing),
                         "the support arcs of neighbouring bolts would touch");
      return 0.5 * width / R;
    }
  } // namespace

  std::vector<double> ring_bolt_angles(const geometry::InternalToothProfile &ring, const RingMeshParameters &p)
  {
    std::vector<double> c;
    if (p.bolts <= 0)
      return c;
    const double R            = ring_outer_radius(ring, p);
    const double w            = bolt_half_angle(p, R);
    const auto [a_begin, a_end] = outer_range(ring, p);
    for (int j = 0; j < p.bolts; ++j)
      {
        double a = 0.5 * pi + p.bolt_phase + 2 * pi * j / p.bolts;
        a        = a_begin + std::fmod(std::fmod(a - a_begin, 2 * pi) + 2 * pi, 2 * pi); // in [a_begin, +2 pi)
        if (a - w > a_begin && a + w < a_end)
          c.push_back(a);
      }
    std::sort(c.begin(), c.end());
    if (c.empty())
      throw InputError("Mesh/Ring/Bolts", std::to_string(p.bolts),
                       "a bolt pattern with at least one support arc inside the " +
                         std::to_string(p.sector_teeth) + "-tooth sector",
                       "change Mesh/Ring/Bolt phase, or use Bolts = 0 (outer arc clamped)");
    return c;
  }

  namespace
  {
    /// Named stops for meshes that would not resolve the teeth or would not fit one machine.
    void check_resolution(const geometry::InternalToothProfile &ring, const RingMeshParameters &p, int n_teeth,
                          int n_fine)
    {
      const double m = ring.parameters().module;
      if (p.h_contact > m)
        throw InputError("Mesh/Ring/h_contact", mm_text(p.h_contact), "<= module = " + mm_text(m),
                         "fewer than ~2 elements along the flank do not resolve the tooth");
      if (p.h_fillet > m)
        throw InputError("Mesh/Ring/h_fillet", mm_text(p.h_fillet), "<= module = " + mm_text(m),
                         "fewer than ~2 elements along the fillet do not resolve the tooth");
      if (p.h_tooth > m)
        throw InputError("Mesh/Ring/h_tooth", mm_text(p.h_tooth), "<= module = " + mm_text(m) + " (0: automatic)");
      // A corner grading finer than h_contact/50 hangs gmsh's size-field meshing (gear_domain).
      if (p.h_corner > 0 && p.h_corner < contact_size(p, m) / 50)
        throw InputError("Mesh/Ring/h_corner", mm_text(p.h_corner),
                         "0 (h_contact/4) or >= h_contact/50 = " + mm_text(contact_size(p, m) / 50));
      const double rim = ring_rim_thickness(ring, p);
      if (!(rim >= p.h_fillet))
        throw InputError(p.rim_thickness > 0 ? "Mesh/Ring/Rim thickness" : "Mesh/Ring/Backup ratio",
                         p.rim_thickness > 0 ? mm_text(rim) : to_string_g(rim / (ring.radii().root - ring.radii().tip)),
                         "a rim of at least h_fillet = " + mm_text(p.h_fillet), "one element through the rim");
      // Estimated cells: the rim at h_body plus each tooth (h_t x half a pitch) at its size.
      const double rf = ring.radii().root, R = rf + rim, h_t = rf - ring.radii().tip;
      const double z = ring.parameters().teeth, tooth_area = h_t * pi * m / 2;
      const double h_fine   = std::min(contact_size(p, m), p.h_fillet), h_coarse = tooth_size(p, m);
      const double estimate = n_teeth / z * pi * (R * R - rf * rf) / (p.h_body * p.h_body) +
                              n_fine * tooth_area / (h_fine * h_fine) +
                              (n_teeth - n_fine) * tooth_area / (h_coarse * h_coarse);
      if (!(estimate <= max_cells))
        throw InputError(p.model == RingMeshParameters::Model::full_ring ? "Mesh/Ring/Model" : "Mesh/Ring/h_body",
                         p.model == RingMeshParameters::Model::full_ring ?
                           "full ring (" + std::to_string(int(z)) + " teeth)" :
                           mm_text(p.h_body),
                         "a mesh of <= 2e6 cells (estimated: " + to_string_g(estimate) + ")",
                         "use Model = sector, or larger h_body/h_tooth");
    }

    /// Which end of segment a (false: t0, true: t1) meets which end of segment b, if any.
    bool shared_end(const geometry::ProfileSegment &a, const geometry::ProfileSegment &b, bool &a_end, bool &b_end)
    {
      const double tol = 1e-9 * a.start().norm();
      for (const bool ea : {false, true})
        for (const bool eb : {false, true})
          if (((ea ? a.end() : a.start()) - (eb ? b.end() : b.start())).norm() < tol)
            {
              a_end = ea, b_end = eb;
              return true;
            }
      return false;
    }

    /// A graded zone at one end of a piece: the part within chord `length` of the end `at_t1`
    /// becomes its own piece of size `size` (nothing when the piece is not longer than that).
    std::vector<BoundaryPiece> graded(const BoundaryPiece &piece, bool at_t1, double length, double size)
    {
      const double t_corner = at_t1 ? piece.t1 : piece.t0, t_far = at_t1 ? piece.t0 : piece.t1;
      const Vec2 corner     = piece.curve.point(t_corner);
      if (!((piece.curve.point(t_far) - corner).norm() > length))
        return {piece};
      const double t_cut = base::find_root_bisection(
        [&](double t) { return (piece.curve.point(t) - corner).norm() - length; }, t_corner, t_far,
        "ring tip-corner zone: chord from the corner");
      BoundaryPiece a = piece, b = piece;
      a.t1 = b.t0 = t_cut;
      (at_t1 ? b : a).size = size;
      return {a, b};
    }

    /// The toothed outline of the model's teeth, counter-clockwise (the profile's order),
    /// with ids, sizes and the corner zones of the fine teeth.
    std::vector<BoundaryPiece> toothed_outline(const geometry::InternalToothProfile &ring,
                                               const RingMeshParameters &p)
    {
      using geometry::SegmentType;
      const int z      = ring.parameters().teeth;
      const double m   = ring.parameters().module;
      const auto &segs = ring.segments();
      const std::vector<int> fine = ring_fine_teeth(p, z);
      const std::set<int> fine_set(fine.begin(), fine.end());
      int tip = -1;
      for (std::size_t s = 0; s < segs.size(); ++s)
        if (segs[s].type == SegmentType::tip)
          tip = int(s);
      // Corner zones: the drive flank and tip land near their common corner get h_corner; a
      // coast flank much coarser than the tip land gets the geometric mean near its corner.
      const double h_contact = contact_size(p, m), h_corner = corner_size(p, m), h_coast = coast_size(p);
      std::vector<std::vector<std::pair<bool, double>>> zones(segs.size()); // (at_t1, size) per segment
      std::vector<double> zone_length(segs.size(), 0);
      for (std::size_t s = 0; s < segs.size() && tip >= 0; ++s)
        {
          bool fe = false, te = false;
          if (segs[s].type != SegmentType::flank || !shared_end(segs[s], segs[std::size_t(tip)], fe, te))
            continue;
          if (segs[s].side == geometry::Side::drive && h_corner < h_contact)
            {
              zones[s].push_back({fe, h_corner}), zone_length[s] = 2 * h_contact;
              zones[std::size_t(tip)].push_back({te, h_corner}), zone_length[std::size_t(tip)] = 2 * h_contact;
            }
          if (segs[s].side == geometry::Side::coast && h_coast > coast_jump_limit * h_contact)
            zones[s].push_back({fe, std::sqrt(h_coast * h_contact)}), zone_length[s] = 2 * h_coast;
        }
      std::vector<BoundaryPiece> out;
      for (const int k : ring_model_teeth(p, z))
        {
          const bool is_fine = fine_set.count(wrap_index(k, z)) > 0;
          for (std::size_t s = 0; s < segs.size(); ++s)
            {
              const auto &sg = segs[s];
              BoundaryPiece piece;
              piece.curve       = ParametricCurve::from(sg.curve, 2 * pi * k / z);
              piece.t0          = sg.t0;
              piece.t1          = sg.t1;
              piece.boundary_id = boundary::tooth_id(wrap_index(k, z), segment_code(sg.type, sg.side));
              piece.tooth       = wrap_index(k, z);
              piece.segment     = int(s);
              const bool flank_like = sg.type == SegmentType::flank || sg.type == SegmentType::tip ||
                                      sg.type == SegmentType::tip_rounding;
              const bool coast = sg.side == geometry::Side::coast && sg.type != SegmentType::fillet &&
                                 sg.type != SegmentType::root;
              piece.size = !is_fine ? tooth_size(p, m) : !flank_like ? p.h_fillet : coast ? h_coast : h_contact;
              std::vector<BoundaryPiece> parts = {piece};
              for (const auto &[at_t1, size] : is_fine ? zones[s] : std::vector<std::pair<bool, double>>{})
                {
                  // Grade the part that holds the corner end (first or last of the pieces so far).
                  BoundaryPiece &end_part = at_t1 ? parts.back() : parts.front();
                  std::vector<BoundaryPiece> g = graded(end_part, at_t1, zone_length[s], size);
                  if (at_t1)
                    parts.pop_back(), parts.insert(parts.end(), g.begin(), g.end());
                  else
                    parts.erase(parts.begin()), parts.insert(parts.begin(), g.begin(), g.end());
                }
              out.insert(out.end(), parts.begin(), parts.end());
            }
        }
      return out;
    }

    /// The pieces in reverse order, each traversed backwards (a clockwise loop).
    std::vector<BoundaryPiece> reversed(std::vector<BoundaryPiece> pieces)
    {
      std::reverse(pieces.begin(), pieces.end());
      for (auto &pc : pieces)
        std::swap(pc.t0, pc.t1);
      return pieces;
    }

    /// Arc of the circle of radius R from polar angle a0 to a1 (> a0), in pieces <= 90 deg.
    void add_arc(std::vector<BoundaryPiece> &out, double R, double a0, double a1, unsigned int id, double size)
    {
      const int n = std::max(1, int(std::ceil((a1 - a0) / (0.5 * pi) - 1e-9)));
      for (int q = 0; q < n; ++q)
        {
          BoundaryPiece b;
          b.curve       = ParametricCurve::circle(Vec2(0, 0), R);
          b.t0          = a0 + (a1 - a0) * q / n;
          b.t1          = a0 + (a1 - a0) * (q + 1) / n;
          b.boundary_id = id;
          b.size        = size;
          out.push_back(b);
        }
    }

    /// The outer circle (or arc) counter-clockwise from a_begin to a_end: one support arc
    /// (boundary::bore) without bolts, else the support arcs and the free arcs between them.
    std::vector<BoundaryPiece> outer_boundary(const geometry::InternalToothProfile &ring, const RingMeshParameters &p)
    {
      const double R              = ring_outer_radius(ring, p);
      const auto [a_begin, a_end] = outer_range(ring, p);
      std::vector<BoundaryPiece> out;
      if (p.bolts == 0)
        {
          add_arc(out, R, a_begin, a_end, boundary::bore, p.h_body);
          return out;
        }
      const double w      = bolt_half_angle(p, R);
      const double h_bolt = std::min(p.h_body, w * R); // at least two edges per support arc
      double a            = a_begin;
      for (const double c : ring_bolt_angles(ring, p))
        {
          add_arc(out, R, a, c - w, boundary::ring_free, p.h_body);
          add_arc(out, R, c - w, c + w, boundary::bore, h_bolt);
          a = c + w;
        }
      add_arc(out, R, a, a_end, boundary::ring_free, p.h_body);
      return out;
    }

    /// A sector cut edge from a to b as straight pieces whose sizes grow from `h_root` at
    /// the toothed end (`from_a`: a is that end) by the growth ratio up to h_body, the law
    /// of the size field inside, so that the fixed node counts of the edge match it.
    std::vector<BoundaryPiece> cut_edge(const Vec2 &a, const Vec2 &b, bool from_a, unsigned int id, double h_root,
                                        const RingMeshParameters &p)
    {
      const double L = (b - a).norm();
      std::vector<double> cuts = {0.0}; // distances from the toothed end
      double d = 0;
      while (d < L)
        {
          const double h = std::min(p.h_body, h_root + (p.growth - 1) * d);
          d              = (L - (d + 2 * h) < h || h >= p.h_body) ? L : d + 2 * h;
          cuts.push_back(d);
        }
      std::vector<BoundaryPiece> out;
      for (std::size_t i = 0; i + 1 < cuts.size(); ++i)
        {
          BoundaryPiece c;
          const Vec2 root = from_a ? a : b, dir = (from_a ? b - a : a - b) / L;
          c.curve       = ParametricCurve::line(root + cuts[i] * dir, root + cuts[i + 1] * dir);
          c.straight    = true;
          c.boundary_id = id;
          c.size        = std::min(p.h_body, h_root + (p.growth - 1) * cuts[i]);
          if (!from_a)
            c.curve = ParametricCurve::line(root + cuts[i + 1] * dir, root + cuts[i] * dir);
          out.push_back(c);
        }
      if (!from_a)
        std::reverse(out.begin(), out.end());
      return out;
    }
  } // namespace

  Domain ring_domain(const geometry::InternalToothProfile &ring, const RingMeshParameters &p)
  {
    p.validate();
    const int z = ring.parameters().teeth;
    if (p.bolts > 0)
      bolt_half_angle(p, ring_outer_radius(ring, p)); // named error before any meshing work
    check_resolution(ring, p, int(ring_model_teeth(p, z).size()), int(ring_fine_teeth(p, z).size()));
    Domain d;
    d.h_body = p.h_body;
    d.growth = p.growth;
    const std::vector<BoundaryPiece> teeth = toothed_outline(ring, p);
    const Vec2 start = teeth.front().start(), end = teeth.back().end();
    Loop outer;
    outer.pieces = outer_boundary(ring, p);
    if (p.model == RingMeshParameters::Model::full_ring)
      {
        if ((start - end).norm() > 1e-9 * start.norm())
          throw InputError("Ring outline", "not closed (gap " + to_string_g((start - end).norm()) + " m)",
                           "a closed outline");
        d.loops.push_back(outer);
        d.loops.push_back(Loop{reversed(teeth)});
      }
    else
      {
        // Outer arc (ccw), cut edge in to the end of the outline, the outline backwards, cut
        // edge out from its start.
        const Vec2 outer_end = outer.pieces.back().end(), outer_start = outer.pieces.front().start();
        const double h_in = teeth.back().size, h_out = teeth.front().size;
        for (const auto &pc : cut_edge(outer_end, end, false, boundary::cut_ccw, h_in, p))
          outer.pieces.push_back(pc);
        for (const auto &pc : reversed(teeth))
          outer.pieces.push_back(pc);
        for (const auto &pc : cut_edge(start, outer_start, true, boundary::cut_cw, h_out, p))
          outer.pieces.push_back(pc);
        d.loops.push_back(outer);
      }
    return d;
  }

  MeshData mesh_ring(const geometry::InternalToothProfile &ring, const RingMeshParameters &p,
                     const std::filesystem::path &msh_file)
  {
    MeshingOptions o;
    o.msh_file          = msh_file;
    o.samples_per_piece = p.spline_samples;
    o.model_name        = "ring_z" + std::to_string(ring.parameters().teeth);
    return mesh_domain(ring_domain(ring, p), o);
  }
} // namespace gearfem::mesh
