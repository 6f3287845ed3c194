// A full gear meshed by tiles (mesh_gear_tiled): gmsh meshes tooth 0 as a one-tooth sector
// down to the gear's inner radius, once with the fine sizes and once with the coarse ones;
// copies are turned into the place of every tooth and joined on the radial cuts, which carry
// one fixed node distribution in every tile. gmsh's time on a full gear grows with its teeth
// (the 76-tooth gear of validation/model_choice: 17.7 s; one tooth of it: 0.14 s), and all
// coarse teeth are the same mesh.
#include "mesh/gear_mesh.h"


#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <set>

namespace gearfem::mesh
{
  namespace
  {
    /// One meshed tile and the vertices of its two cuts, ordered by radius.
    struct Tile
    {
      MeshData mesh;
      std::vector<unsigned int> cw, ccw;
    };

    /// The vertices on the edges with boundary id `id`, by increasing radius.
    std::vector<unsigned int> cut_vertices(const MeshData &m, unsigned int id)
    {
      std::set<unsigned int> s;
      for (const auto &e : m.boundary_edges)
        if (e.boundary_id == id)
          s.insert(e.v0), s.insert(e.v1);
      std::vector<unsigned int> v(s.begin(), s.end());
      std::sort(v.begin(), v.end(),
                [&](unsigned a, unsigned b) { return m.vertices[a].norm() < m.vertices[b].norm(); });
      return v;
    }

    /// Whether the radii of two cut vertex lists agree (same count, within `tol` [m]).
    bool same_radii(const MeshData &a, const std::vector<unsigned int> &va, const MeshData &b,
                    const std::vector<unsigned int> &vb, double tol)
    {
      if (va.size() != vb.size() || va.size() < 2)
        return false;
      for (std::size_t i = 0; i < va.size(); ++i)
        if (std::abs(a.vertices[va[i]].norm() - b.vertices[vb[i]].norm()) > tol)
          return false;
      return true;
    }

    /// The node distribution of a cut, from the outline inwards: `graded` edges growing by
    /// `ratio` over `graded_length` [m], then `uniform` equal edges (0: the whole cut graded).
    struct CutNodes
    {
      int graded = 0, uniform = 1;
      double ratio = 1.0, graded_length = 0.0;
      double h0 = 0.0; ///< the first edge [m]: also the size of every tile's half root lands
    };

    /// The tile domain of tooth 0 (fine or coarse); with cuts (clockwise side `cw`,
    /// counter-clockwise `ccw`), each radial cut is split into its graded outer part and
    /// uniform inner part with those node counts, and the half root land beside it takes the
    /// cut's first size.
    Domain tile_domain(const geometry::ToothProfile &tooth, const GearMeshParameters &p, double ri, bool fine,
                       const CutNodes *cw = nullptr, const CutNodes *ccw_cut = nullptr)
    {
      GearMeshParameters t = p;
      t.model        = GearMeshParameters::Model::sector;
      t.sector_teeth = 1;
      t.tiled        = false;
      t.fine_teeth   = fine ? "0" : "1";
      if (t.rim_thickness <= 0)
        t.bore_radius = ri; // the full gear's bore, not a sector's default rim
      Domain d = gear_domain(tooth, t);
      if (!cw || !ccw_cut)
        return d;
      // The half root lands at the cuts take the cut's first size (the size field grades from
      // there as the cut does).
      auto &outline = d.loops.front().pieces;
      outline.front().size = cw->h0;
      for (std::size_t i = 1; i < outline.size(); ++i)
        if (outline[i].boundary_id == boundary::cut_ccw)
          outline[i - 1].size = ccw_cut->h0;
      std::vector<BoundaryPiece> pieces;
      for (const auto &piece : d.loops.front().pieces)
        {
          const bool ccw = piece.boundary_id == boundary::cut_ccw;
          const CutNodes *cut = ccw ? ccw_cut : cw;
          if (!ccw && piece.boundary_id != boundary::cut_cw)
            {
              pieces.push_back(piece);
              continue;
            }
          // cut_ccw runs from the outline inwards, cut_cw from the inner circle outwards.
          const Vec2 outer = ccw ? piece.start() : piece.end(), inner = ccw ? piece.end() : piece.start();
          if (cut->uniform == 0)
            {
              BoundaryPiece graded = piece;
              graded.edges         = cut->graded;
              graded.progression   = ccw ? cut->ratio : 1.0 / cut->ratio;
              pieces.push_back(graded);
              continue;
            }
          const Vec2 mid   = outer + cut->graded_length / (inner - outer).norm() * (inner - outer);
          BoundaryPiece graded = piece, uniform = piece;
          graded.edges         = cut->graded;
          uniform.edges        = cut->uniform;
          graded.curve         = ccw ? ParametricCurve::line(outer, mid) : ParametricCurve::line(mid, outer);
          graded.progression   = ccw ? cut->ratio : 1.0 / cut->ratio;
          uniform.curve        = ccw ? ParametricCurve::line(mid, inner) : ParametricCurve::line(inner, mid);
          graded.t0 = uniform.t0 = 0.0;
          graded.t1 = uniform.t1 = 1.0;
          if (ccw)
            pieces.push_back(graded), pieces.push_back(uniform);
          else
            pieces.push_back(uniform), pieces.push_back(graded);
        }
      d.loops.front().pieces = pieces;
      return d;
    }
    /// The tiles turned into place (`placed[j]` is tooth j's) and joined on their cuts: cut j,
    /// between teeth j - 1 and j, is tooth j's clockwise cut; each copy takes its tooth's ids
    /// and exact curves (as gear_domain builds them).
    MeshData join_tiles(const geometry::ToothProfile &tooth, const std::vector<const Tile *> &placed, double ri)
    {
      const int z = int(placed.size());
      MeshData out;
      // Cut j lies between teeth j - 1 and j: the clockwise cut of tooth j, turned into place.
      std::vector<unsigned int> cut_first(std::size_t(z) + 1, 0);
      for (int j = 0; j < z; ++j)
        {
          const Tile &t              = *placed[std::size_t(j)];
          cut_first[std::size_t(j)] = unsigned(out.vertices.size());
          for (const unsigned v : t.cw)
            out.vertices.push_back(tooth.rotate_to_tooth(t.mesh.vertices[v], j));
        }
      cut_first[std::size_t(z)] = cut_first[0];
      const auto &segs = tooth.segments();
      for (int j = 0; j < z; ++j)
        {
          const Tile &t      = *placed[std::size_t(j)];
          const double angle = j * tooth.angular_pitch();
          std::vector<unsigned int> map(t.mesh.vertices.size(), ~0u);
          for (std::size_t i = 0; i < t.cw.size(); ++i)
            map[t.cw[i]] = cut_first[std::size_t(j)] + unsigned(i);
          for (std::size_t i = 0; i < t.ccw.size(); ++i)
            map[t.ccw[i]] = cut_first[std::size_t(j) + 1] + unsigned(i);
          for (std::size_t v = 0; v < map.size(); ++v)
            if (map[v] == ~0u)
              {
                map[v] = unsigned(out.vertices.size());
                out.vertices.push_back(tooth.rotate_to_tooth(t.mesh.vertices[v], j));
              }
          for (const auto &c : t.mesh.cells)
            out.cells.push_back({map[c[0]], map[c[1]], map[c[2]], map[c[3]]});
          // The tile's pieces as this tooth's: its exact curves (as gear_domain builds them) and
          // ids; the cuts are interior here.
          std::vector<int> piece_of(t.mesh.pieces.size(), -1);
          for (std::size_t i = 0; i < t.mesh.pieces.size(); ++i)
            {
              BoundaryPiece piece = t.mesh.pieces[i];
              if (piece.segment >= 0)
                {
                  piece.curve       = ParametricCurve::from(segs[std::size_t(piece.segment)].curve, angle);
                  piece.tooth       = j;
                  piece.boundary_id = boundary::tooth_id(j, boundary::Code(boundary::code_of(piece.boundary_id)));
                }
              else if (piece.boundary_id == boundary::bore)
                {
                  piece.curve = ParametricCurve::circle(Vec2(0, 0), ri);
                  piece.t0 += angle, piece.t1 += angle;
                }
              else
                continue;
              piece_of[i] = int(out.pieces.size());
              out.pieces.push_back(piece);
            }
          for (const auto &e : t.mesh.boundary_edges)
            if (piece_of[std::size_t(e.piece)] >= 0)
              {
                const int k = piece_of[std::size_t(e.piece)];
                out.boundary_edges.push_back({map[e.v0], map[e.v1], out.pieces[std::size_t(k)].boundary_id, k});
              }
        }
      return out;
    }

    /// Tile kind `k` (bit 2: the fine tooth; bits 1 and 0: a fine cut on the clockwise and
    /// counter-clockwise side). A coarse tooth's tile whose first quad recombination leaves
    /// triangles is meshed again with its outline 5, 10, 15 and 20 % finer (the cuts keep
    /// their nodes) before the mesher's own remedies: its first remedy grades the size field
    /// to the short half root lands, and such a tile has about three times the cells (the
    /// 41-tooth pinion of validation/model_choice's random 1 at h_tooth 2 mm: 91 cells against
    /// 35 at 1.8 mm, 18 000 of the 64 000 DoFs of the choice's companion level). A coarse tooth
    /// carries no contact and no fillet peak; a finer outline only adds accuracy there.
    MeshData mesh_tile(const geometry::ToothProfile &tooth, const GearMeshParameters &p, double ri, int k,
                       const CutNodes cut[2], const MeshingOptions &options)
    {
      const auto domain = [&](const GearMeshParameters &q) {
        return tile_domain(tooth, q, ri, k & 4, &cut[(k >> 1) & 1], &cut[k & 1]);
      };
      if (!(k & 4))
        {
          MeshingOptions first = options;
          first.grade_short    = false;
          first.fallbacks      = false;
          const double h       = tooth_size(p, tooth.parameters().rack.module);
          for (const double f : {1.0, 0.95, 0.9, 0.85, 0.8})
            {
              GearMeshParameters q = p;
              q.h_tooth            = f * h;
              try
                {
                  return mesh_domain(domain(q), first);
                }
              catch (const InputError &)
                {
                  // triangles left or an inverted cell: the next size
                }
            }
        }
      return mesh_domain(domain(p), options);
    }
  } // namespace

  MeshData mesh_gear_tiled(const geometry::ToothProfile &tooth, const GearMeshParameters &p,
                           const MeshingOptions &options, std::string *why)
  {
    const auto refuse = [&](const std::string &reason) {
      if (why)
        *why = reason;
      return MeshData();
    };
    if (p.model != GearMeshParameters::Model::full_gear || !p.tooth_angles.empty() || tooth.teeth() < 3)
      return refuse("tiles serve full gears of 3 teeth or more without tooth placement offsets");
    const auto t0            = std::chrono::steady_clock::now();
    const int z              = tooth.teeth();
    const double ri          = inner_radius(p, tooth);
    const std::vector<int> f = fine_teeth(p, z);
    const std::set<int> fine(f.begin(), f.end());
    const auto is_fine = [&](int j) { return fine.count(((j % z) + z) % z) > 0; };

    // The cuts run from the outline (the middle of a root land) to the inner circle, edges
    // growing by the growth ratio from the root land's size, as the size field grows away from
    // the root land, up to h_body; then h_body. A cut beside a fine tooth starts at the fine
    // teeth's root size (cut 1), one between coarse teeth at the coarse (cut 0).
    CutNodes cut[2];
    double length = 0;
    for (int k = 0; k < 2; ++k)
      {
        const Domain d     = tile_domain(tooth, p, ri, k == 1);
        const auto &pieces = d.loops.front().pieces;
        cut[k].h0          = std::min(p.h_body, pieces.front().size > 0 ? pieces.front().size : p.h_body);
        for (const auto &piece : pieces)
          if (piece.boundary_id == boundary::cut_ccw)
            length = (piece.end() - piece.start()).norm();
      }
    for (auto &c : cut)
      {
        c.ratio         = p.growth;
        c.graded        = std::max(1, int(std::ceil(std::log(p.h_body / c.h0) / std::log(c.ratio))));
        c.graded_length = c.h0 * (std::pow(c.ratio, c.graded) - 1) / (c.ratio - 1);
        if (c.graded_length < length - 0.5 * p.h_body)
          c.uniform = std::max(1, int(std::lround((length - c.graded_length) / p.h_body)));
        else
          {
            // A rim shorter than the grading: the whole cut graded, its first edge near h0.
            c.graded        = std::max(1, int(std::lround(std::log(1 + length * (c.ratio - 1) / c.h0) / std::log(c.ratio))));
            c.graded_length = length;
            c.uniform       = 0;
          }
      }

    // Tile kinds: (fine tooth, fine cut on the clockwise side, fine cut on the counter-clockwise side).
    const auto kind = [&](int j) {
      return 4 * is_fine(j) + 2 * (is_fine(j) || is_fine(j - 1)) + (is_fine(j) || is_fine(j + 1));
    };
    std::map<int, Tile> tiles;
    MeshingOptions o = options;
    o.msh_file.clear();
    bool subdivided = false;
    for (int j = 0; j < z; ++j)
      {
        const int k = kind(j);
        if (tiles.count(k))
          continue;
        o.model_name = options.model_name + "_tile" + std::to_string(k);
        Tile &t      = tiles[k];
        t.mesh       = mesh_tile(tooth, p, ri, k, cut, o);
        t.cw         = cut_vertices(t.mesh, boundary::cut_cw);
        t.ccw        = cut_vertices(t.mesh, boundary::cut_ccw);
        subdivided   = subdivided || t.mesh.subdivided;
      }
    // Each cut must carry the same nodes in the two tiles that meet on it; otherwise the
    // whole gear is meshed. gmsh places the graded nodes of a cut in the two tiles up to about
    // 1e-9 of the tip radius apart (4e-11 m on the 28-tooth gear of validation/model_choice's
    // random 1 at h_fillet 0.208 mm, which a tolerance of 1e-9 r_tip sent to the whole-gear
    // mesher: 5.9 s instead of 0.5 s); the join takes one tile's nodes, so a mismatch far below
    // any element only moves the other tile's cells by as much.
    const double tol = 1e-7 * tooth.radii().tip;
    for (int j = 0; j < z; ++j)
      {
        const Tile &a = tiles.at(kind(j)), &b = tiles.at(kind(j - 1));
        if (!same_radii(a.mesh, a.cw, b.mesh, b.ccw, tol))
          return refuse("the tiles of teeth " + std::to_string(j - 1) + " and " + std::to_string(j) +
                        " do not share their cut's nodes (" + std::to_string(a.cw.size()) + " and " +
                        std::to_string(b.ccw.size()) + (a.mesh.subdivided || b.mesh.subdivided ? ", a tile subdivided)" : ")"));
      }

    std::vector<const Tile *> placed;
    for (int j = 0; j < z; ++j)
      placed.push_back(&tiles.at(kind(j)));
    MeshData out   = join_tiles(tooth, placed, ri);
    out.subdivided = subdivided;
    out.mesh_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (quality(out).n_inverted > 0)
      return refuse("an inverted cell");
    return out;
  }
} // namespace gearfem::mesh
