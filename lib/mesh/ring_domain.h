#pragma once
// The body of an internal gear (ring) to mesh, in its own body frame (ring centre at the
// origin, tooth 0 axis +y, the frame of geometry::InternalToothProfile): a full ring (all z
// teeth, the toothed outline inside, an outer circle of radius r_f2 + rim thickness outside)
// or a sector of N teeth (radial cut edges through the middle of the tooth spaces, as the
// external sector model). No deal.II, no gmsh. SI units (m, rad).
//
// Support of the outer circle:
//  - clamped: the whole outer circle (the outer arc of a sector) has id boundary::bore, the
//    id that build_gear_body clamps for an external gear's bore;
//  - bolts: n short arcs of the outer circle centred at the bolt (or spline) angles have id
//    boundary::bore and the rest of the outer circle is free (id boundary::ring_free). A
//    caller that clamps boundary::bore then models each bolt or spline tooth as a rigid
//    support of the rim over its arc (no slip, no rotation about the arc), and the rim
//    between the supports bends freely. Bolt holes through the rim are not modelled.
//
// Boundary ids of the toothed outline are those of external gears (mesh::boundary::tooth_id
// with the codes of domain.h): the segments of InternalToothProfile carry their side, so the
// ring's DRIVE flank (the right, x > 0 flank of tooth 0, pushed by the pinion's drive flank
// in the pair frame of geometry/internal.h) gets code flank_drive.
#include "geometry/internal_profile.h"
#include "mesh/domain.h"

#include <filesystem>
#include <string>
#include <vector>

namespace gearfem::mesh
{
  /// Mesh parameters of a ring body, in SI units. Sizes as GearMeshParameters.
  struct RingMeshParameters
  {
    enum class Model
    {
      full_ring, ///< all z teeth, outer circle outside
      sector     ///< N teeth, radial cut edges, outer arc
    };
    Model model      = Model::full_ring;
    int sector_teeth = 3; ///< N (sector only), >= 1
    /// Rim thickness below the tooth roots, from the root circle r_f2 out to the outer circle
    /// [m]; 0: backup_ratio times the tooth height.
    double rim_thickness = 0;
    /// Backup ratio m_B = rim thickness / tooth height h_t (AGMA 2001-D04, rim thickness
    /// factor K_B; h_t = r_f2 - r_a2), used when rim_thickness is 0; 0: 1.2 (the smallest
    /// m_B at which AGMA's K_B is 1). Give one of rim_thickness and backup_ratio.
    double backup_ratio = 0;
    double h_contact    = 0.25e-3; ///< size on the drive flanks and tips of the fine teeth [m]; 0: m/30
    double h_fillet     = 0.25e-3; ///< size on the fillets and root lands of the fine teeth [m]
    double h_coast      = 0;       ///< size on the coast flanks of the fine teeth [m]; 0: h_fillet
    /// Size at the sharp drive tip corners of the fine teeth (last 2 h_contact of the drive
    /// flank and of the tip land) [m]; 0: h_contact/4; >= h_contact: no grading.
    double h_corner = 0;
    double h_body   = 3e-3; ///< largest element size (rim, outer circle) [m]
    double h_tooth  = 0;    ///< size on the other teeth [m]; 0: min(h_body, 0.4 m)
    double growth   = 1.2;  ///< size growth ratio away from fine boundaries (> 1)
    /// Teeth with the fine sizes: "auto" (teeth -2..2 of a full ring, all teeth of a sector)
    /// or a comma-separated list of tooth indices (negative allowed, taken modulo z).
    std::string fine_teeth = "auto";
    /// Number of bolts (or spline teeth) that support the outer circle; 0: clamped all round.
    int bolts = 0;
    /// Polar angle of bolt 0 from the tooth-0 axis (+y), counter-clockwise [rad]; bolt j
    /// stands at bolt_phase + 2 pi j / bolts from +y.
    double bolt_phase = 0;
    /// Arc length of each support arc on the outer circle [m]; 0: a tenth of the bolt spacing.
    double bolt_width = 0;
    int spline_samples = 24; ///< gmsh spline points per boundary piece

    /// Throws InputError naming the `Mesh` entry for N < 1, sizes < 0 or > h_body, growth
    /// <= 1, negative rim thickness or backup ratio (or both given), bolts < 0, bad
    /// fine-teeth lists.
    void validate() const;
  };

  /// Element size on the drive flanks and tips of the fine teeth [m]: h_contact, or m/30 when 0
  /// (the rule of mesh::contact_size for external gears).
  double ring_contact_size(const RingMeshParameters &p, double module);
  /// Rim thickness from r_f2 to the outer circle [m] (rim_thickness, or m_B h_t).
  double ring_rim_thickness(const geometry::InternalToothProfile &ring, const RingMeshParameters &p);
  /// Outer radius r_f2 + rim thickness [m].
  double ring_outer_radius(const geometry::InternalToothProfile &ring, const RingMeshParameters &p);
  /// Tooth indices of the model in outline order (all z, or the N sector teeth around 0).
  std::vector<int> ring_model_teeth(const RingMeshParameters &p, int z);
  /// Tooth indices (0 <= k < z) that get the fine sizes.
  std::vector<int> ring_fine_teeth(const RingMeshParameters &p, int z);
  /// Polar angles (from +x, counter-clockwise) of the centres of the support arcs that the
  /// model holds [rad]: every bolt of a full ring, the bolts whose arc lies inside a sector.
  std::vector<double> ring_bolt_angles(const geometry::InternalToothProfile &ring, const RingMeshParameters &p);

  /// The domain of the ring body: the outer circle (or the sector's outer arc, cut edges
  /// ids 2 and 3) counter-clockwise and the toothed outline clockwise (the material is
  /// outside it), ids 1000 (tooth + 1) + code; support ids as stated above.
  Domain ring_domain(const geometry::InternalToothProfile &ring, const RingMeshParameters &p);

  /// Mesh the ring body with gmsh (and write `msh_file` when not empty).
  MeshData mesh_ring(const geometry::InternalToothProfile &ring, const RingMeshParameters &p,
                     const std::filesystem::path &msh_file = {});
} // namespace gearfem::mesh
