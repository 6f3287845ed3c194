#include "system_deflection/solid_face.h"

#include "base/errors.h"
#include "base/units.h"
#include "three_d/face_compliance.h"

#include <memory>

namespace gearfem::system_deflection
{
  mesh::GearMeshParameters solid_mesh(const solve::GearContactInput &section, const helical::SlicingOptions &o, int i)
  {
    mesh::GearMeshParameters mp = section.mesh[i - 1];
    const double h = o.solid.element_size > 0 ? o.solid.element_size : o.helix.m_n / 3;
    if (h > 2 * o.helix.m_n)
      throw InputError("Helical/3-D element size", to_string_g(h / units::mm) + " mm",
                       "0 (m_n/3) or > 0 up to 2 m_n = " + to_string_g(2 * o.helix.m_n / units::mm) + " mm");
    mp.model        = mesh::GearMeshParameters::Model::sector;
    mp.sector_teeth = o.solid.sector_teeth;
    mp.h_contact = mp.h_fillet = mp.h_coast = mp.h_corner = mp.h_tooth = h;
    mp.h_body        = 2 * h;
    mp.rim_thickness = 0;
    mp.fine_teeth    = "auto";
    mp.flank_split_radii.clear();
    mp.tooth_angles.clear();
    mp.refinements = 0;
    mp.tiled       = false;
    return mp;
  }

  helical::SlicingOptions with_solid_face(const solve::GearContactInput &section, helical::SlicingOptions o,
                                          std::ostream *out)
  {
    if (o.model != helical::FaceModel::solid)
      return o;
    section.require_external("Helical/Model = 3-D FE");
    const auto &pair = *section.pair;
    std::shared_ptr<const three_d::FaceCompliance> face[2];
    for (int i = 1; i <= 2; ++i)
      {
        // The section at z is the pair at roll angle phi1 + z roll_per_length: gear i's body is
        // turned there by d(angle_i)/d(phi1) times that (central difference of the placement).
        const double d  = 1e-4;
        const double da = (pair.placement(i, d).angle - pair.placement(i, -d).angle) / (2 * d);
        three_d::FaceOptions fo;
        fo.face_width       = o.helix.face_width;
        fo.slices           = o.slices;
        fo.layers_per_slice = o.solid.layers_per_slice;
        fo.degree           = o.solid.degree;
        fo.radii            = o.solid.flank_points;
        fo.twist            = da * o.helix.roll_per_length;
        face[i - 1] = std::make_shared<const three_d::FaceCompliance>(pair.gear(i), solid_mesh(section, o, i),
                                                                      section.material[i - 1], fo, out);
        if (out)
          *out << "3-D body of gear " << i << ": " << face[i - 1]->n_cells() << " cells, " << face[i - 1]->n_dofs()
               << " DoFs, " << to_string_g(face[i - 1]->seconds()) << " s\n";
      }
    o.face_seconds = face[0]->seconds() + face[1]->seconds();
    o.face_dofs    = face[0]->n_dofs() + face[1]->n_dofs();
    o.face_root = [face0 = face[0], face1 = face[1]](int g, const std::vector<double> &f, const std::vector<double> &r) {
      return (g == 1 ? face0 : face1)->section_load(f, r);
    };
    o.face = [f1 = face[0], f2 = face[1]](const std::vector<double> &r1, const std::vector<double> &r2) {
      return Eigen::MatrixXd(f1->correction(r1) + f2->correction(r2));
    };
    return o;
  }
} // namespace gearfem::system_deflection
