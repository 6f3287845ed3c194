#pragma once
// An external pinion meshing inside an internal gear (ring), as the contact model places
// them: the MeshingPair of a generated pinion (ToothProfile) and a shaper-cut ring
// (InternalToothProfile), with the kinematics of internal.h. SI units (m, rad).
//
// Frame (meshing_pair.h, internal.h): pinion centre at the origin, ring centre at (0, -a),
// C = (0, r_w1). The pinion turns counter-clockwise and drives; the ring turns counter-
// clockwise at z1/z2 of its speed. At phi1 = 0 the pinion's drive flank (the left flank of
// its tooth 0, boundary code flank_drive) and the ring's drive flank (the right flank of its
// tooth 0, code flank_drive) touch at C:
//   pinion angle phase1 + phi1, phase1 = -s_w1/(2 r_w1);
//   ring angle   phase2 + phi1 z1/z2, phase2 = +s_w2/(2 r_w2),
// with s_w the arc tooth thicknesses on the working pitch circles (the pinion's from its
// generated outline, the ring's from its involute).
#include "geometry/internal.h"
#include "geometry/internal_profile.h"
#include "geometry/meshing_pair.h"
#include "geometry/profile.h"

#include <string>
#include <vector>

namespace gearfem::geometry
{
  class InternalGearPair : public MeshingPair
  {
  public:
    /// Throws InputError (naming the entry) when the pinion and ring do not mesh: different
    /// module or pressure angle, no line of action, contact ratio < 1, negative backlash, or
    /// any interference of internal.h except tip fouling on radial withdrawal (a warning:
    /// the pinion is then assembled axially). `center_distance` 0: zero backlash from the
    /// shifts. `ring_face_width` 0: the pinion's.
    InternalGearPair(ToothProfile pinion, InternalToothProfile ring, double center_distance = 0.0,
                     double ring_face_width = 0.0);

    const ToothProfile &pinion() const { return pinion_; }
    const InternalToothProfile &ring() const { return ring_; }
    const InternalMesh &mesh() const { return mesh_; }
    double circumferential_backlash() const { return jt_; } ///< on the working pitch circle [m]
    const std::vector<std::string> &warnings() const { return warnings_; }

    bool is_internal() const override { return true; }
    int teeth(int i) const override;
    double module() const override { return mesh_.in.module; }
    double base_radius(int i) const override { return i == 1 ? mesh_.rb1 : mesh_.rb2; }
    double working_pitch_radius(int i) const override { return i == 1 ? mesh_.rw1 : mesh_.rw2; }
    double working_pressure_angle() const override { return mesh_.alpha_w; }
    double base_pitch() const override { return mesh_.pb; }
    double ratio() const override { return double(teeth(2)) / teeth(1); }
    double center_distance() const override { return mesh_.a; }
    double contact_ratio() const override { return mesh_.contact_ratio; }
    double face_width(int i) const override { return i == 1 ? pinion_.parameters().face_width : ring_width_; }
    const std::vector<LoaPoint> &line_of_action() const override { return mesh_.loa; }
    const LoaPoint &point(const std::string &name) const override { return mesh_.point(name); }
    Placement placement(int i, double phi1) const override;
    Vec2 path_point(double phi1) const override;
    bool is_involute() const override { return true; }
    bool closed_rack(int i) const override { return i == 1 && pinion_.rack().closed(); }
    /// Pinion: (r_tf1^2 - r^2)/(2 r_b1); ring (tip inside): (r^2 - r_a2^2)/(2 r_b2).
    double flank_length_to_tip(int i, double r) const override;
    bool beyond_tip_form(int i, double r, double tol) const override;
    /// sqrt(r1^2 - r_b1^2) and -sqrt(r2^2 - r_b2^2) (the ring's flank is concave).
    std::array<double, 2> radii_of_curvature(const Vec2 &x, const std::array<Placement, 2> &P) const override;
    double relief_at_radius(int i, double r) const override { return i == 1 ? pinion_.relief_at_radius(r) : 0.0; }
    bool has_relief(int i) const override;

  private:
    ToothProfile pinion_;
    InternalToothProfile ring_;
    InternalMesh mesh_;
    double ring_width_ = 0, jt_ = 0, phase1_ = 0, phase2_ = 0;
    std::vector<std::string> warnings_;
  };

  /// A short hex fingerprint of the internal pair's defining numbers (as
  /// geometry_fingerprint of an external pair, with the cutter's).
  std::string geometry_fingerprint(const InternalGearPair &pair);
} // namespace gearfem::geometry
