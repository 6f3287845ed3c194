// gmsh model construction for a Domain, all-quad meshing, and extraction of MeshData.
#include "mesh/domain.h"
#include "base/units.h"

#include "base/errors.h"
#include "geometry/closest.h"

#include <gmsh.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <mutex>
#include <set>
#include <unistd.h>

namespace gearfem::mesh
{
  namespace boundary
  {
    std::string name(unsigned int id)
    {
      switch (id)
        {
          case bore:
            return "bore";
          case cut_cw:
            return "cut_cw";
          case cut_ccw:
            return "cut_ccw";
          case outer:
            return "outer";
          case ring_free:
            return "ring_free";
        }
      if (id < 1000)
        return "boundary_" + std::to_string(id);
      static const char *codes[] = {"?",           "flank_drive",     "flank_coast",
                                    "fillet_drive", "fillet_coast",   "tip",
                                    "tip_round_drive", "tip_round_coast", "root_drive",
                                    "root_coast"};
      const unsigned int c = code_of(id);
      return "tooth" + std::to_string(tooth_of(id)) + "_" + (c <= 9 ? codes[c] : "?");
    }
  } // namespace boundary

  namespace
  {
    /// geometry::newton_closest on the curve.
    double newton_closest(const ParametricCurve &c, const Vec2 &q, double lo, double hi, double t, double a, double b,
                          Vec2 &x, Vec2 &x1, bool &newton)
    {
      const auto eval = [&c](double s, Vec2 &p, Vec2 &p1, Vec2 &p2) { c.evaluate(s, p, p1, p2); };
      return geometry::newton_closest(eval, q, lo, hi, t, a, b, x, x1, newton);
    }
  } // namespace

  void ParametricCurve::evaluate(double t, Vec2 &p, Vec2 &p1, Vec2 &p2) const
  {
    if (all)
      all(t, p, p1, p2);
    else
      p = point(t), p1 = d1(t), p2 = d2(t);
  }

  double ParametricCurve::closest_parameter(const Vec2 &q, double lo, double hi) const
  {
    if (lo > hi)
      std::swap(lo, hi);
    std::vector<Vec2> samples(closest_samples + 1);
    for (int i = 0; i <= closest_samples; ++i)
      samples[i] = point(lo + (hi - lo) * i / closest_samples);
    return closest_parameter(q, lo, hi, samples);
  }

  double ParametricCurve::closest_parameter(const Vec2 &q, double lo, double hi, const std::vector<Vec2> &samples) const
  {
    const auto eval = [this](double s, Vec2 &p, Vec2 &p1, Vec2 &p2) { evaluate(s, p, p1, p2); };
    return geometry::closest_parameter(eval, [&samples](int i) { return samples[std::size_t(i)]; }, q, lo, hi,
                                       closest_samples);
  }

  double ParametricCurve::closest_parameter_from(const Vec2 &q, double lo, double hi, double t0, bool &ok) const
  {
    Vec2 x, x1;
    return closest_parameter_from(q, lo, hi, t0, ok, x, x1);
  }

  double ParametricCurve::closest_parameter_from(const Vec2 &q, double lo, double hi, double t0, bool &ok, Vec2 &x,
                                                 Vec2 &x1) const
  {
    if (lo > hi)
      std::swap(lo, hi);
    const double dt = (hi - lo) / closest_samples;
    const double a = std::max(lo, t0 - dt), b = std::min(hi, t0 + dt);
    ok = a > lo && b < hi;
    if (!ok)
      return t0;
    // Newton first: converged by a Newton step strictly inside (a, b), it has found a root
    // of f with f' > 0, the minimum the bracket check below would admit (f has one root in
    // a bracket of a 32nd of a piece). Two evaluations fewer than checking first.
    bool newton   = false;
    const double t = newton_closest(*this, q, lo, hi, std::clamp(t0, a, b), a, b, x, x1, newton);
    if (newton && t > a && t < b)
      return t;
    const auto f = [&](double s) {
      Vec2 p, p1, p2;
      evaluate(s, p, p1, p2);
      return (p - q).dot(p1);
    };
    // The minimum must lie strictly inside the bracket: f < 0 at a, f > 0 at b.
    ok = f(a) < 0 && f(b) > 0;
    if (!ok)
      return t0;
    return newton_closest(*this, q, lo, hi, std::clamp(t0, a, b), a, b, x, x1, newton);
  }

  ParametricCurve ParametricCurve::from(const geometry::CurvePtr &curve, double angle)
  {
    const double c = std::cos(angle), s = std::sin(angle);
    auto rot       = [c, s](const Vec2 &v) { return Vec2(c * v.x() - s * v.y(), s * v.x() + c * v.y()); };
    ParametricCurve pc;
    pc.point = [curve, rot](double t) { return rot(curve->point(t)); };
    pc.d1    = [curve, rot](double t) { return rot(curve->d1(t)); };
    pc.d2    = [curve, rot](double t) { return rot(curve->d2(t)); };
    pc.all   = [curve, rot](double t, Vec2 &p, Vec2 &p1, Vec2 &p2) {
      curve->evaluate(t, p, p1, p2);
      p = rot(p), p1 = rot(p1), p2 = rot(p2);
    };
    return pc;
  }

  ParametricCurve ParametricCurve::circle(const Vec2 &c, double r)
  {
    ParametricCurve pc;
    pc.point = [c, r](double t) { return Vec2(c + r * Vec2(std::cos(t), std::sin(t))); };
    pc.d1    = [r](double t) { return Vec2(r * Vec2(-std::sin(t), std::cos(t))); };
    pc.d2    = [r](double t) { return Vec2(-r * Vec2(std::cos(t), std::sin(t))); };
    return pc;
  }

  ParametricCurve ParametricCurve::line(const Vec2 &a, const Vec2 &b)
  {
    ParametricCurve pc;
    pc.point = [a, b](double t) { return Vec2(a + t * (b - a)); };
    pc.d1    = [a, b](double) { return Vec2(b - a); };
    pc.d2    = [](double) { return Vec2(0.0, 0.0); };
    return pc;
  }

  namespace
  {
    /// gmsh is a global singleton: serialise its use within the process.
    std::mutex gmsh_mutex;

    struct GmshSession
    {
      GmshSession()
      {
        gmsh::initialize();
        gmsh::option::setNumber("General.Terminal", 0);
        gmsh::logger::start();
      }
      ~GmshSession()
      {
        try
          {
            gmsh::logger::stop();
            gmsh::finalize();
          }
        catch (...)
          {}
      }
      std::string last_errors() const
      {
        std::string e;
        try
          {
            gmsh::logger::getLastError(e);
          }
        catch (...)
          {}
        return e;
      }
    };

    [[noreturn]] void gmsh_failure(const std::string &what, const std::string &detail)
    {
      throw InputError("Mesh", "gmsh " + what, "a valid all-quad mesh",
                       detail.empty() ? "gmsh failed; try other mesh sizes" : detail);
    }

    void validate_domain(const Domain &d)
    {
      require_greater("Mesh/h_body", d.h_body, 0.0, "m");
      require_greater("Mesh/Growth ratio", d.growth, 1.0);
      if (d.loops.empty() || d.loops[0].pieces.empty())
        throw InputError("Mesh", "empty domain", "at least one closed loop");
      for (const auto &loop : d.loops)
        for (std::size_t i = 0; i < loop.pieces.size(); ++i)
          {
            const auto &a = loop.pieces[i], &b = loop.pieces[(i + 1) % loop.pieces.size()];
            const double gap = (a.end() - b.start()).norm();
            if (!(gap <= 1e-9 * (1.0 + a.end().norm())))
              throw InputError("Mesh", "loop gap " + to_string_g(gap) + " m",
                               "closed loops (consecutive pieces share end points)");
          }
    }
  } // namespace

  namespace
  {
    /// The gmsh model of a Domain: curve tags and the pieces they came from.
    struct GmshModel
    {
      std::map<int, int> curve_to_piece; ///< gmsh curve tag -> index in MeshData::pieces
      std::vector<int>   piece_to_curve; ///< index in MeshData::pieces -> gmsh curve tag
      int                surface = -1;
    };

    /// Phase 1: points, curves (a spline through samples, or a line), loops and the plane
    /// surface; the pieces are copied to out.pieces in curve order.
    GmshModel build_geometry(const Domain &domain, const MeshingOptions &options, MeshData &out)
    {
      namespace geo = gmsh::model::geo;
      GmshModel m;
      std::vector<int> loop_tags;
      for (const auto &loop : domain.loops)
        {
          std::vector<int> curves;
          const int first_point = -1;
          int prev_end          = first_point, loop_start = -1;
          for (std::size_t i = 0; i < loop.pieces.size(); ++i)
            {
              const auto &piece = loop.pieces[i];
              const int n       = piece.straight ? 1 : std::max(2, options.samples_per_piece);
              std::vector<int> pts;
              for (int j = 0; j <= n; ++j)
                {
                  if (j == 0 && prev_end >= 0)
                    {
                      pts.push_back(prev_end);
                      continue;
                    }
                  if (j == n && i + 1 == loop.pieces.size())
                    {
                      pts.push_back(loop_start);
                      continue;
                    }
                  const Vec2 p = piece.curve.point(piece.t0 + (piece.t1 - piece.t0) * j / n);
                  pts.push_back(geo::addPoint(p.x(), p.y(), 0.0));
                  if (i == 0 && j == 0)
                    loop_start = pts.back();
                }
              prev_end      = pts.back();
              const int tag = piece.straight ? geo::addLine(pts[0], pts[1]) : geo::addSpline(pts);
              curves.push_back(tag);
              m.curve_to_piece[tag] = int(out.pieces.size());
              m.piece_to_curve.push_back(tag);
              out.pieces.push_back(piece);
            }
          loop_tags.push_back(geo::addCurveLoop(curves));
        }
      m.surface = geo::addPlaneSurface(loop_tags);
      geo::synchronize();
      return m;
    }

    /// Phase 2: physical groups, one per boundary id, plus the body.
    void add_physical_groups(const GmshModel &m, const MeshData &out)
    {
      std::map<unsigned int, std::vector<int>> groups;
      for (const auto &[tag, piece] : m.curve_to_piece)
        groups[out.pieces[piece].boundary_id].push_back(tag);
      for (const auto &[id, tags] : groups)
        {
          gmsh::model::addPhysicalGroup(1, tags, int(id));
          gmsh::model::setPhysicalName(1, int(id), boundary::name(id));
        }
      gmsh::model::addPhysicalGroup(2, {m.surface}, 1);
      gmsh::model::setPhysicalName(2, 1, "body");
    }

    /// Arc length of a piece (polyline of 256 chords).
    double piece_length(const BoundaryPiece &piece)
    {
      double length = 0;
      Vec2 prev     = piece.start();
      for (int j = 1; j <= 256; ++j)
        {
          const Vec2 p = piece.curve.point(piece.t0 + (piece.t1 - piece.t0) * j / 256);
          length += (p - prev).norm();
          prev = p;
        }
      return length;
    }

    /// A piece shorter than this fraction of its size is one short edge between longer ones
    /// (the root lands of coarse teeth); Blossom then can leave triangle pairs at its ends.
    constexpr double short_piece_ratio = 0.5;

    /// Whether a piece of the domain is shorter than short_piece_ratio times its size.
    bool has_short_piece(const Domain &domain)
    {
      for (const auto &loop : domain.loops)
        for (const auto &piece : loop.pieces)
          {
            const double h = piece.size > 0 ? piece.size : domain.h_body;
            if (piece_length(piece) < short_piece_ratio * h)
              return true;
          }
      return false;
    }

    /// Phase 3: size field. For each distinct fine size, distance to its pieces and a
    /// threshold growing linearly (h + (g - 1) d, the continuous form of a geometric
    /// progression); the minimum with h_body is the background mesh.
    void add_size_field(const Domain &domain, const GmshModel &m, const MeshData &out, bool grade_short)
    {
      std::map<double, std::vector<double>> by_size;
      std::map<double, double> longest; // per size: the longest piece [m] (graded mesh only)
      for (const auto &[tag, piece] : m.curve_to_piece)
        {
          double h = out.pieces[piece].size > 0 ? out.pieces[piece].size : domain.h_body;
          const double length = grade_short ? piece_length(out.pieces[piece]) : 0.0;
          // Snapped down to a sqrt(2) ladder: one distance field per rung, not per piece.
          if (grade_short && length < short_piece_ratio * h)
            h *= std::pow(2.0, 0.5 * std::floor(2.0 * std::log2(length / h)));
          if (h > 0 && h < domain.h_body)
            {
              by_size[h].push_back(tag);
              longest[h] = std::max(longest[h], length);
            }
        }
      namespace field = gmsh::model::mesh::field;
      std::vector<double> thresholds;
      for (const auto &[h, tags] : by_size)
        {
          const int dist = field::add("Distance");
          field::setNumbers(dist, "CurvesList", tags);
          // 400 samples per curve; the graded mesh (after a failed first one) takes four per
          // element of the group's longest curve (distance within h/8), a smaller search tree.
          const double n_samples = grade_short ? std::clamp(std::ceil(4.0 * longest[h] / h), 16.0, 400.0) : 400.0;
          field::setNumber(dist, "NumPointsPerCurve", n_samples);
          const int thr = field::add("Threshold");
          field::setNumber(thr, "InField", dist);
          field::setNumber(thr, "SizeMin", h);
          field::setNumber(thr, "SizeMax", domain.h_body);
          field::setNumber(thr, "DistMin", 0.5 * h);
          field::setNumber(thr, "DistMax", 0.5 * h + (domain.h_body - h) / (domain.growth - 1.0));
          thresholds.push_back(thr);
        }
      const int constant = field::add("MathEval");
      field::setString(constant, "F", to_string_g(domain.h_body));
      thresholds.push_back(constant);
      const int fmin = field::add("Min");
      field::setNumbers(fmin, "FieldsList", thresholds);
      field::setAsBackgroundMesh(fmin);
    }

    /// Phase 4: node counts per curve from the arc length and the piece size, with an even
    /// number of edges per loop (added to the loop's longest curve): an odd boundary cannot
    /// be closed by quads only, and Blossom full-quad then leaves triangles.
    void set_curve_node_counts(const Domain &domain, const GmshModel &m, const MeshData &out)
    {
      std::size_t first = 0;
      for (std::size_t l = 0; l < domain.loops.size(); ++l)
        {
          const std::size_t n_pieces = domain.loops[l].pieces.size();
          std::vector<int> n_edges(n_pieces);
          std::vector<double> lengths(n_pieces);
          int total = 0;
          for (std::size_t i = 0; i < n_pieces; ++i)
            {
              const auto &piece = out.pieces[first + i];
              const double h = piece.size > 0 ? std::min(piece.size, domain.h_body) : domain.h_body;
              const double length = piece_length(piece);
              lengths[i] = piece.edges > 0 ? 0.0 : length / h; // a fixed count is never bumped
              n_edges[i] = piece.edges > 0 ? piece.edges : std::max(1, int(std::lround(length / h)));
              total += n_edges[i];
            }
          if (total % 2 == 1)
            ++n_edges[std::max_element(lengths.begin(), lengths.end()) - lengths.begin()];
          for (std::size_t i = 0; i < n_pieces; ++i)
            {
              const auto &piece = out.pieces[first + i];
              if (piece.edges > 0 && piece.progression != 1.0)
                gmsh::model::mesh::setTransfiniteCurve(m.piece_to_curve[first + i], n_edges[i] + 1, "Progression",
                                                       piece.progression);
              else
                gmsh::model::mesh::setTransfiniteCurve(m.piece_to_curve[first + i], n_edges[i] + 1);
            }
          first += n_pieces;
        }
    }

    /// Number of elements of the surface that are not quadrilaterals.
    std::size_t n_non_quads(const GmshModel &m)
    {
      std::vector<int> t;
      std::vector<std::vector<std::size_t>> et, en;
      gmsh::model::mesh::getElements(t, et, en, 2, m.surface);
      std::size_t n = 0;
      for (std::size_t k = 0; k < t.size(); ++k)
        if (t[k] != 3)
          n += et[k].size();
      return n;
    }

    /// Phase 5: generate the mesh (Blossom recombination); the number of elements left that
    /// are not quadrilaterals (0 for a good mesh: the boundary loops are even).
    std::size_t generate_recombined(const MeshingOptions &options, const GmshModel &m)
    {
      gmsh::option::setNumber("Mesh.Smoothing", options.smoothing_steps);
      gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
      gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
      gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
      gmsh::option::setNumber("Mesh.Algorithm", options.algorithm);
      gmsh::option::setNumber("Mesh.RecombineAll", 1);
      gmsh::option::setNumber("Mesh.RecombinationAlgorithm", 1); // Blossom
      gmsh::option::setNumber("Mesh.MshFileVersion", 4.1);
      gmsh::model::mesh::generate(2);
      return n_non_quads(m);
    }

    /// Phase 5, last resort: Blossom occasionally fails on a valid triangulation. Retry
    /// Frontal-Delaunay with a perturbed triangulation (random factor), then MeshAdapt; should
    /// a triangle remain, remesh at twice the size and split every element into quads
    /// (Mesh.SubdivisionAlgorithm = 1), which guarantees an all-quad mesh (lower quality) and
    /// sets out.subdivided.
    void recombination_fallbacks(const MeshingOptions &options, const GmshModel &m, MeshData &out)
    {
      for (int attempt = 1; attempt <= 3 && n_non_quads(m) > 0; ++attempt)
        {
          gmsh::model::mesh::clear();
          gmsh::option::setNumber("Mesh.RandomFactor", 1e-9 * (1 + 10 * attempt));
          gmsh::option::setNumber("Mesh.Smoothing", options.smoothing_steps + attempt);
          gmsh::model::mesh::generate(2);
        }
      if (n_non_quads(m) > 0 && options.algorithm != 1)
        {
          gmsh::model::mesh::clear();
          gmsh::option::setNumber("Mesh.Algorithm", 1);
          gmsh::model::mesh::generate(2);
        }
      if (n_non_quads(m) > 0)
        {
          gmsh::model::mesh::clear();
          gmsh::option::setNumber("Mesh.MeshSizeFactor", 2.0);
          gmsh::option::setNumber("Mesh.RecombinationAlgorithm", 1);
          gmsh::option::setNumber("Mesh.SubdivisionAlgorithm", 1);
          gmsh::model::mesh::generate(2);
          out.subdivided = true;
        }
    }

    /// Phase 6: vertices, counter-clockwise quads and boundary edges per curve from gmsh;
    /// `tags` receives the gmsh node tag of each vertex.
    void extract_mesh(const GmshModel &m, MeshData &out, std::vector<std::size_t> &tags)
    {
      // Nodes.
      std::vector<std::size_t> node_tags;
      std::vector<double> coords, param;
      gmsh::model::mesh::getNodes(node_tags, coords, param, -1, -1, true, false);
      std::map<std::size_t, unsigned int> index;
      for (std::size_t i = 0; i < node_tags.size(); ++i)
        if (index.emplace(node_tags[i], unsigned(out.vertices.size())).second)
          {
            out.vertices.emplace_back(coords[3 * i], coords[3 * i + 1]);
            tags.push_back(node_tags[i]);
          }

      // Quads.
      std::vector<int> types;
      std::vector<std::vector<std::size_t>> elem_tags, elem_nodes;
      gmsh::model::mesh::getElements(types, elem_tags, elem_nodes, 2, m.surface);
      for (std::size_t k = 0; k < types.size(); ++k)
        {
          if (types[k] != 3)
            gmsh_failure("left " + std::to_string(elem_tags[k].size()) +
                           " non-quadrilateral elements (type " + std::to_string(types[k]) + ")",
                         "recombination failed; change the mesh sizes");
          for (std::size_t e = 0; e < elem_tags[k].size(); ++e)
            {
              std::array<unsigned int, 4> q;
              for (int j = 0; j < 4; ++j)
                q[j] = index.at(elem_nodes[k][4 * e + j]);
              // gmsh order is cyclic; make it counter-clockwise, then lexicographic.
              const Vec2 &a = out.vertices[q[0]], &b = out.vertices[q[1]], &c = out.vertices[q[2]],
                         &d  = out.vertices[q[3]];
              const double area2 = (c - a).x() * (d - b).y() - (c - a).y() * (d - b).x();
              if (area2 < 0)
                std::swap(q[1], q[3]);
              out.cells.push_back({q[0], q[1], q[3], q[2]});
            }
        }
      if (out.cells.empty())
        gmsh_failure("produced no elements", "");

      // Boundary edges per curve.
      for (const auto &[tag, piece] : m.curve_to_piece)
        {
          gmsh::model::mesh::getElements(types, elem_tags, elem_nodes, 1, tag);
          for (std::size_t k = 0; k < types.size(); ++k)
            for (std::size_t e = 0; e < elem_tags[k].size(); ++e)
              out.boundary_edges.push_back({index.at(elem_nodes[k][2 * e]),
                                            index.at(elem_nodes[k][2 * e + 1]),
                                            out.pieces[piece].boundary_id, piece});
        }
    }

    /// Phase 9 (optional): the .msh file of the final vertices (snapped onto the exact curves
    /// and untangled: the mesh the solver uses), written through a temporary file and renamed.
    void write_msh(const MeshData &out, const std::vector<std::size_t> &tags, const std::filesystem::path &target)
    {
      for (std::size_t v = 0; v < out.vertices.size(); ++v)
        gmsh::model::mesh::setNode(tags[v], {out.vertices[v].x(), out.vertices[v].y(), 0.0}, {});
      auto tmp = target.parent_path() /
                 ("." + target.stem().string() + ".tmp" + std::to_string(::getpid()) + ".msh");
      gmsh::write(tmp.string());
      std::filesystem::rename(tmp, target);
    }

    /// Phase 7: snap boundary vertices onto the exact curves (gmsh meshed a spline through
    /// samples); a vertex shared by two pieces is their common end point.
    void snap_boundary_vertices(MeshData &out)
    {
      std::vector<int> on_piece(out.vertices.size(), -1);
      std::vector<char> corner(out.vertices.size(), 0);
      for (const auto &e : out.boundary_edges)
        for (unsigned v : {e.v0, e.v1})
          {
            if (on_piece[v] >= 0 && on_piece[v] != e.piece)
              corner[v] = 1;
            on_piece[v] = e.piece;
          }
      for (std::size_t v = 0; v < out.vertices.size(); ++v)
        {
          if (on_piece[v] < 0)
            continue;
          const auto &piece = out.pieces[on_piece[v]];
          Vec2 &x           = out.vertices[v];
          if (corner[v])
            x = (x - piece.start()).norm() < (x - piece.end()).norm() ? piece.start() : piece.end();
          else if (!piece.straight)
            x = piece.curve.point(piece.curve.closest_parameter(x, piece.t0, piece.t1));
        }
    }
  } // namespace

  MeshData mesh_domain(const Domain &domain, const MeshingOptions &options)
  {
    validate_domain(domain);
    std::lock_guard<std::mutex> lock(gmsh_mutex);
    const auto t_start = std::chrono::steady_clock::now();
    MeshData out;
    std::vector<std::size_t> tags;
    // Phases 1-8, in a gmsh session of their own. `grade`: when the first mesh is not all
    // quads and the outline has short pieces, mesh again with the size field graded to them
    // (their length as their size) before the retries of phase 5. Returns whether the
    // graded mesh was taken.
    const auto mesh_once = [&](bool grade) {
      GmshSession session;
      bool graded = false;
      out = MeshData();
      tags.clear();
      try
        {
          const auto build = [&](bool grade_short) {
            if (grade_short)
              gmsh::model::remove();
            out.pieces.clear();
            gmsh::model::add(options.model_name);
            const GmshModel m = build_geometry(domain, options, out);
            add_physical_groups(m, out);
            add_size_field(domain, m, out, grade_short);
            set_curve_node_counts(domain, m, out);
            return m;
          };
          GmshModel model  = build(false);
          std::size_t left = generate_recombined(options, model);
          if (grade && left > 0 && has_short_piece(domain))
            {
              // Blossom leaves triangle pairs where a piece is one edge much shorter than its
              // neighbours (the root lands between coarse teeth of large gears: 8 of the 69
              // roots of the 23/69 m 4 gear at h_contact m/30); grading the size field to
              // those pieces meshes them at once, where the retries below failed alike and
              // subdivided.
              model  = build(true);
              left   = generate_recombined(options, model);
              graded = true;
            }
          if (left > 0 && !options.fallbacks)
            throw RecombinationFailed("Mesh",
                                      "gmsh Blossom recombination left " + std::to_string(left) +
                                        " non-quadrilateral elements",
                                      "an all-quad mesh at the first attempt", "fallbacks off: try other sizes");
          if (left > 0)
            recombination_fallbacks(options, model, out);
          extract_mesh(model, out, tags);
        }
      catch (const std::string &e)
        {
          gmsh_failure("error: " + e, session.last_errors());
        }
      catch (const std::out_of_range &)
        {
          gmsh_failure("returned inconsistent node tags", "");
        }
      snap_boundary_vertices(out);
      untangle_inverted_cells(out); // phase 8
      if (!options.msh_file.empty())
        try
          {
            write_msh(out, tags, options.msh_file);
          }
        catch (const std::string &e)
          {
            gmsh_failure("error writing " + options.msh_file.string() + ": " + e, session.last_errors());
          }
      return graded;
    };
    // A graded mesh that snapping to the exact outline leaves with an inverted cell (the
    // Parker gear at h_contact = h_fillet = 0.05 mm, a fillet cell) is not used: the mesh is
    // made again without the graded pass, through the retries of phase 5.
    if (mesh_once(options.grade_short) && quality(out).n_inverted > 0 && options.fallbacks)
      mesh_once(false);
    out.mesh_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count();

    const QualityReport q = quality(out);
    if (q.n_inverted > 0)
      gmsh_failure("produced " + std::to_string(q.n_inverted) + " inverted cells" + inverted_cell_location(out),
                   "refine the mesh near strongly curved boundaries (Mesh/h_fillet, Mesh/h_contact)");
    return out;
  }

  void write_mesh_msh(const MeshData &mesh, const std::filesystem::path &file, const std::string &model_name)
  {
    std::lock_guard<std::mutex> lock(gmsh_mutex);
    GmshSession session;
    try
      {
        gmsh::model::add(model_name);
        std::vector<std::size_t> tags(mesh.vertices.size());
        std::vector<double> xyz;
        xyz.reserve(3 * mesh.vertices.size());
        for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
          {
            tags[v] = v + 1;
            xyz.insert(xyz.end(), {mesh.vertices[v].x(), mesh.vertices[v].y(), 0.0});
          }
        const int surface = gmsh::model::addDiscreteEntity(2);
        gmsh::model::mesh::addNodes(2, surface, tags, xyz);
        std::vector<std::size_t> quads, quad_nodes;
        std::size_t element = 0;
        for (const auto &c : mesh.cells)
          {
            quads.push_back(++element);
            for (const unsigned v : {c[0], c[1], c[3], c[2]}) // gmsh order: counter-clockwise
              quad_nodes.push_back(v + 1);
          }
        gmsh::model::mesh::addElementsByType(surface, 3, quads, quad_nodes);
        gmsh::model::addPhysicalGroup(2, {surface}, 1);
        gmsh::model::setPhysicalName(2, 1, "body");
        std::map<unsigned int, std::vector<std::size_t>> by_id;
        for (const auto &e : mesh.boundary_edges)
          by_id[e.boundary_id].insert(by_id[e.boundary_id].end(), {e.v0 + 1u, e.v1 + 1u});
        for (const auto &[id, nodes] : by_id)
          {
            const int curve = gmsh::model::addDiscreteEntity(1);
            std::vector<std::size_t> lines(nodes.size() / 2);
            for (auto &l : lines)
              l = ++element;
            gmsh::model::mesh::addElementsByType(curve, 1, lines, nodes);
            gmsh::model::addPhysicalGroup(1, {curve}, int(id));
            gmsh::model::setPhysicalName(1, int(id), boundary::name(id));
          }
        gmsh::option::setNumber("Mesh.MshFileVersion", 4.1);
        auto tmp = file.parent_path() / ("." + file.stem().string() + ".tmp" + std::to_string(::getpid()) + ".msh");
        gmsh::write(tmp.string());
        std::filesystem::rename(tmp, file);
      }
    catch (const std::string &e)
      {
        gmsh_failure("error writing " + file.string() + ": " + e, session.last_errors());
      }
  }

  Domain annulus_domain(double r_inner, double r_outer, double h)
  {
    require_greater("Mesh/Bore radius", r_inner, 0.0, "m");
    if (!(r_outer > r_inner))
      throw InputError("Mesh/Outer radius", to_string_g(r_outer) + " m",
                       "> bore radius " + to_string_g(r_inner) + " m");
    using units::pi;
    Domain d;
    d.h_body = h;
    d.growth = 1.3;
    Loop outer, inner;
    for (int k = 0; k < 4; ++k)
      {
        BoundaryPiece o;
        o.curve       = ParametricCurve::circle(Vec2(0, 0), r_outer);
        o.t0          = k * pi / 2;
        o.t1          = (k + 1) * pi / 2;
        o.boundary_id = boundary::outer;
        outer.pieces.push_back(o);
        BoundaryPiece i = o;
        i.curve         = ParametricCurve::circle(Vec2(0, 0), r_inner);
        i.t0            = -k * pi / 2;
        i.t1            = -(k + 1) * pi / 2; // holes run clockwise
        i.boundary_id   = boundary::bore;
        inner.pieces.push_back(i);
      }
    d.loops = {outer, inner};
    return d;
  }

  Domain rectangle_domain(double length, double height, double h)
  {
    require_greater("length", length, 0.0, "m");
    require_greater("height", height, 0.0, "m");
    const Vec2 c[4] = {{0, -height / 2}, {length, -height / 2}, {length, height / 2}, {0, height / 2}};
    const unsigned ids[4] = {12, 13, 14, 11};
    Domain d;
    d.h_body = h;
    Loop l;
    for (int k = 0; k < 4; ++k)
      {
        BoundaryPiece p;
        p.curve       = ParametricCurve::line(c[k], c[(k + 1) % 4]);
        p.boundary_id = ids[k];
        p.straight    = true;
        l.pieces.push_back(p);
      }
    d.loops = {l};
    return d;
  }
} // namespace gearfem::mesh
