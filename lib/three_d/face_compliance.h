#pragma once
// The far field of a tooth's face in three dimensions, for the combined (Vijayakar-type) 3-D
// contact of a gear pair (docs/three_d.md). One gear, as a sector whose middle tooth (tooth 0)
// carries the load on its drive flank:
// - a coarse 3-D body: the section mesh (straight-sided cells) extruded over the face width,
//   twisted along the helix, clamped at the bore and the cuts (three_d/solid_body.h);
// - the same section in 2-D on the same straight cells and elements, in the plane model of
//   the sections (plane stress or strain), as thick as one slice.
// The load is a strip: a unit transverse force spread uniformly over the width of one slice
// along the flank line at radius r, in the direction normal to the helicoid (transverse part
// the involute normal, axial part from the twist); the compliance is the work-conjugate
// displacement (the strip's mean along the same direction), so that both tables are symmetric.
// Tabulated on a grid of radii over the drive flank (linear in r between its points):
//   solid(i, r_i, j, r_j)  3-D: strip j loaded at r_j, strip i read at r_i [m/N];
//   section(r_i, r_j)      2-D: the same for one slice alone [m/N].
// correction(r) = C3 - diag(C2) over the slices of one tooth: what the 3-D body adds to (or
// takes from) independent 2-D sections, their coupling across the face, the face ends and the
// plane condition. The coarse mesh's own error near the load is common to both tables and
// cancels; the near field of the contact comes from gearfem's exact 2-D sections. No deal.II
// in this header.
#include "fem/elasticity.h"
#include "geometry/profile.h"
#include "mesh/gear_mesh.h"

#include <Eigen/Dense>

#include <filesystem>
#include <memory>
#include <ostream>
#include <vector>

namespace gearfem::three_d
{
  struct FaceOptions
  {
    double face_width   = 0; ///< b [m]
    int slices          = 21;
    int layers_per_slice = 1; ///< cells across one slice
    unsigned degree     = 2;  ///< FE_Q(p), {1, 2}
    int radii           = 7;  ///< grid points over the drive flank, >= 2
    /// Rotation of the transverse section per unit axial length, counter-clockwise in the
    /// body frame, about the middle of the face [rad/m] (0: spur).
    double twist = 0;
    /// InputError naming the `3-D` entry of the first value out of range.
    void validate() const;
  };

  class FaceCompliance
  {
  public:
    /// `mesh`: the coarse section (a sector; its sizes are the 3-D model's); `material`: E, nu
    /// and the plane model of the 2-D sections. Progress (i/N) to `progress` when not null.
    FaceCompliance(const geometry::ToothProfile &tooth, const mesh::GearMeshParameters &mesh,
                   const fem::Elasticity &material, const FaceOptions &options, std::ostream *progress = nullptr);
    ~FaceCompliance();
    FaceCompliance(const FaceCompliance &) = delete;
    FaceCompliance &operator=(const FaceCompliance &) = delete;

    double solid(int i, double r_i, int j, double r_j) const;
    double section(double r_i, double r_j) const;
    /// C3 - diag(C2) over the slices at radii r (one per slice) [m/N].
    Eigen::MatrixXd correction(const std::vector<double> &r) const;

    /// The fillet of a slice in 3-D: under transverse strip forces `force` [N] at radii r (one
    /// per slice), the force each slice's 2-D section would carry to reach the 3-D body's
    /// largest tangential stress on the drive fillet of that slice [N] (both on the coarse
    /// cells: the ratio keeps their error out). A uniform load on a face without Poisson's
    /// coupling gives `force` back.
    std::vector<double> section_load(const std::vector<double> &force, const std::vector<double> &r) const;

    /// The 3-D body under transverse strip forces `force` [N] at radii r (one per slice): its
    /// VTU (displacement, and its copy times `scale`), written atomically.
    void write_vtu(const std::vector<double> &force, const std::vector<double> &r, const std::filesystem::path &file,
                   double scale = 1.0) const;

    const std::vector<double> &radii() const;
    const FaceOptions &options() const;
    unsigned int n_dofs() const;     ///< of the 3-D body
    unsigned int n_cells() const;    ///< of the 3-D body
    double seconds() const;          ///< to mesh, factorise and tabulate [s]

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
  };
} // namespace gearfem::three_d
