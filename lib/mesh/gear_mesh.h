#pragma once
// The gear body to mesh, in its own body frame (centre at the origin, tooth 0 axis +y):
// a full gear (all z teeth, bore) or a sector of N teeth (rim below the root circle,
// straight radial cut edges; the 3-tooth model of Siasos 2010 generalised). No deal.II, no gmsh.
// SI units (m).
#include "geometry/profile.h"
#include "mesh/domain.h"

#include <string>
#include <vector>

namespace gearfem::mesh
{
  /// Largest h_coast / h_contact ratio meshed without a transition at the coast tip corner
  /// (measured on the Parker gear: 2.5 and 2.7 mesh, 3.3 and 4 leave triangles).
  inline constexpr double coast_jump_limit = 2.0;

  /// The `Mesh` section, in SI units.
  struct GearMeshParameters
  {
    enum class Model
    {
      full_gear, ///< all z teeth, bore circle inside
      sector     ///< N teeth, rim of given thickness, radial cut edges
    };
    Model model             = Model::full_gear;
    int sector_teeth        = 3;       ///< N (sector only), >= 1
    double h_contact        = 0.25e-3; ///< element size on the drive flanks and tips of the fine teeth [m]; 0: m_n/30
    double h_fillet         = 0.25e-3; ///< element size on the fillets and root of the fine teeth [m]
    double h_coast          = 0;       ///< size on the coast flank and coast tip rounding of the fine teeth [m]; 0: h_fillet
    /// Size at the sharp drive tip corners of the fine teeth [m]: on the last 2 h_contact of
    /// the drive flank and of the tip land before the corner, where a corner contact is
    /// singular; 0: h_contact/4; h_corner >= h_contact: no grading.
    double h_corner         = 0;
    double h_body           = 3e-3;    ///< largest element size inside [m]
    double h_tooth          = 0;       ///< size on the other teeth [m]; 0: min(h_body, 0.4 m)
    double growth           = 1.2;     ///< size growth ratio away from fine boundaries (> 1)
    double bore_radius      = 0;       ///< [m]; 0: half the root radius
    double rim_thickness    = 0;       ///< below the root circle [m]; 0: bore (full gear) or 2.75 m (sector)
    /// Teeth that get the fine sizes: "auto" (teeth -2..2 of a full gear: those in contact
    /// over a mesh cycle around tooth 0 plus one on each side; all teeth of a sector), a
    /// comma-separated list of tooth indices (negative allowed, taken modulo z), or "loaded",
    /// which the solve input turns into the list of the teeth its positions load
    /// (geometry::loaded_teeth) before any mesh is built.
    std::string fine_teeth = "auto";
    /// Radii [m] at which the flanks of the fine teeth are split into separate gmsh curves
    /// (same boundary id), so that mesh vertices sit at the edges of a load patch.
    std::vector<double> flank_split_radii;
    unsigned int refinements = 0; ///< global refinements after import
    int spline_samples       = 24; ///< gmsh spline points per outline segment
    /// Full gear: mesh one fine and one coarse tooth tile and turn copies into place
    /// (mesh_gear_tiled); false, a sector or tooth_angles: the whole outline in one gmsh run.
    bool tiled = false;
    /// Not a `Mesh` entry: false makes a failed first quad recombination throw
    /// RecombinationFailed instead of the slow retries and the subdivision fallback
    /// (MeshingOptions::fallbacks), so that the model choice tries other sizes (model_choice/).
    bool quad_fallbacks = true;
    /// Extra placement angles delta_k [rad] of the teeth, counter-clockwise: tooth k (0 <= k < z)
    /// stands at 2 pi k / z + delta_k (a pitch deviation built into the geometry). Empty: every
    /// tooth at its nominal pitch; else z values. Consecutive teeth meet on their root lands at
    /// the mean of their offsets (gear_domain). Not a `Mesh` entry: set by a caller that builds
    /// deviations into the geometry (docs/deviations.md).
    std::vector<double> tooth_angles;

    /// Throws InputError naming the `Mesh` entry for N < 1, sizes <= 0, h_contact or
    /// h_fillet > h_body, growth <= 1, bad fine-teeth lists.
    void validate() const;
  };

  /// Element size on the drive flanks and tips of the fine teeth [m]: h_contact, or m_n/30
  /// when it is 0 (about 6 nodes of a quadratic mesh across a Hertz patch at a typical
  /// design stress, which keeps the STE ripple of the node-to-segment contact below 0.1 %).
  double contact_size(const GearMeshParameters &p, double module);
  /// Element size at a sharp drive tip corner [m]: h_corner, or contact_size/4 when 0
  /// (never above contact_size).
  double corner_size(const GearMeshParameters &p, double module);
  /// Element size on the coast flanks of the fine teeth [m]: h_coast, or h_fillet when 0.
  double coast_size(const GearMeshParameters &p);
  /// Element size on the outline of the other (coarse) teeth [m]: h_tooth, or min(h_body, 0.4 m)
  /// when 0.
  double tooth_size(const GearMeshParameters &p, double module);
  /// Tooth indices (0 <= k < z) that get fine sizes. Throws InputError for "loaded" (not
  /// resolved: only inputs with Solve positions take it).
  std::vector<int> fine_teeth(const GearMeshParameters &p, int z);
  /// `teeth` as a Fine teeth list ("-1,0,1"), each index times `sign`, sorted.
  std::string fine_teeth_list(const std::vector<int> &teeth, int sign);
  /// Tooth indices of the model in outline order (all z, or the N sector teeth around 0).
  std::vector<int> model_teeth(const GearMeshParameters &p, int z);
  /// Radius of the inner boundary (bore or fixed rim) [m]. Throws InputError when it
  /// leaves no material (bore radius >= root radius, rim thickness >= root radius).
  double inner_radius(const GearMeshParameters &p, const geometry::ToothProfile &tooth);
  /// Cells of one machine's gear mesh at most: beyond it meshing stops with a named error.
  inline constexpr double max_cells = 2e6;
  /// Estimated quadrilaterals of the mesh of `tooth` with `p`: the body ring (tip to bore) at
  /// h_body plus each modelled tooth (area ~ 2.25 m x pi m / 2) at its own size. The size check
  /// of meshing compares it with max_cells; the model choice stops refining before it.
  double estimated_cells(const GearMeshParameters &p, const geometry::ToothProfile &tooth);
  /// Largest difference |delta_k - delta_(k-1)| [rad] of the tooth placement offsets of
  /// neighbouring teeth that gear_domain accepts: the angle of half a root land (each root land
  /// gives or takes half the difference and keeps at least half its length); 0 when the outline
  /// has no root land arc (the fillets of neighbouring teeth meet at a point: rotated teeth
  /// would overlap or leave a gap there, so no offsets are accepted).
  double max_tooth_angle_step(const geometry::ToothProfile &tooth);
  /// Checks offsets for `tooth` (InputError naming `entry`): empty or z finite values, and
  /// neighbouring differences within max_tooth_angle_step.
  void check_tooth_angles(const geometry::ToothProfile &tooth, const std::vector<double> &angles,
                          const std::string &entry);
  /// Boundary-id code of an outline segment (mesh::boundary::Code).
  boundary::Code segment_code(geometry::SegmentType type, geometry::Side side);

  /// The domain of the gear body: outline pieces with ids 1000 (tooth + 1) + code, the
  /// bore (id 1) and, for sectors, the cut edges (ids 2, 3). With tooth_angles, tooth k is
  /// turned by delta_k and the root lands where teeth k - 1 and k meet become arcs of the root
  /// circle that meet at the mean angle (delta_(k-1) + delta_k) / 2 past the nominal one: an arc
  /// of the root circle turned about the centre stays on it, so the outline closes exactly.
  Domain gear_domain(const geometry::ToothProfile &tooth, const GearMeshParameters &p);

  /// A full gear meshed by tiles: tooth 0 as a one-tooth sector down to the gear's inner
  /// radius, once with the fine sizes and once with the coarse ones, joined on radial cuts
  /// that carry one fixed node distribution (geometric from the root land's size at the
  /// outline to h_body at the bore), then turned into the place of every tooth, with the
  /// boundary ids and exact curves of that tooth. Empty MeshData (no cells) when the tiles'
  /// cuts do not match (a tile that gmsh subdivided) or the rim is too thin for the graded cut,
  /// with the reason in `why`: the caller meshes the whole gear.
  MeshData mesh_gear_tiled(const geometry::ToothProfile &tooth, const GearMeshParameters &p,
                           const MeshingOptions &options, std::string *why = nullptr);

  /// Mesh the gear body with gmsh (and write `msh_file` when not empty).
  MeshData mesh_gear(const geometry::ToothProfile &tooth, const GearMeshParameters &p,
                     const std::filesystem::path &msh_file = {});
} // namespace gearfem::mesh
