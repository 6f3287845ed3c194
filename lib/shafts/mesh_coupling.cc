#include "shafts/mesh_coupling.h"

#include "base/errors.h"

#include <cmath>

namespace gearfem::shafts
{
  namespace
  {
    struct Frame
    {
      Eigen::Vector3d P, Q, e, t, n;
      double r1 = 0, r2 = 0; // pitch radii
    };

    Frame frame(const System &system, const MeshLayout &m)
    {
      m.validate(system);
      const auto &p = system.shafts[std::size_t(m.pinion_shaft)], &g = system.shafts[std::size_t(m.gear_shaft)];
      Frame f;
      f.P = Eigen::Vector3d(p.x, p.y, 0), f.Q = Eigen::Vector3d(g.x, g.y, 0);
      const double a = (f.Q - f.P).norm();
      f.e = (f.Q - f.P) / a;
      f.t = Eigen::Vector3d(-f.e.y(), f.e.x(), 0) * double(m.drive_sense);
      f.n = std::cos(m.alpha_wt) * f.t + std::sin(m.alpha_wt) * f.e;
      f.r1 = m.pitch_radius_1, f.r2 = a - m.pitch_radius_1;
      return f;
    }
  } // namespace

  void MeshLayout::validate(const System &system) const
  {
    const int n = int(system.shafts.size());
    for (const int s : {pinion_shaft, gear_shaft})
      if (s < 0 || s >= n)
        throw InputError("mesh shaft", std::to_string(s), "a shaft of the system (0 to " + std::to_string(n - 1) + ")");
    if (pinion_shaft == gear_shaft)
      throw InputError("mesh shafts", std::to_string(pinion_shaft) + " and " + std::to_string(gear_shaft),
                       "two different shafts");
    if (!(face_width > 0))
      throw InputError("mesh face width", mm_text(face_width), "> 0");
    const std::pair<int, double> ends[2] = {{pinion_shaft, pinion_face_start}, {gear_shaft, gear_face_start}};
    for (const auto &[s, z0] : ends)
      {
        const double L = system.shafts[std::size_t(s)].length();
        if (!(z0 >= 0 && z0 + face_width <= L * (1 + 1e-12)))
          throw InputError("mesh face start", mm_text(z0), "0 to " + mm_text(L - face_width) + " (the face on its shaft)");
      }
    const auto &p = system.shafts[std::size_t(pinion_shaft)], &g = system.shafts[std::size_t(gear_shaft)];
    const double a = std::hypot(g.x - p.x, g.y - p.y);
    if (!(a > 0))
      throw InputError("mesh centre distance", mm_text(a), "> 0 (parallel axes apart)");
    if (!(pitch_radius_1 > 0 && pitch_radius_1 < a))
      throw InputError("mesh pitch radius", mm_text(pitch_radius_1), "0 to the centre distance " + mm_text(a));
    if (!(alpha_wt > 0 && alpha_wt < M_PI / 2))
      throw InputError("mesh pressure angle", to_string_g(alpha_wt * 180 / M_PI) + " deg", "0 to 90 deg");
    if (!(std::abs(beta_b) < M_PI / 2 - 1e-6))
      throw InputError("mesh base helix angle", to_string_g(beta_b * 180 / M_PI) + " deg", "-90 to 90 deg");
    if (drive_sense != 1 && drive_sense != -1)
      throw InputError("mesh drive sense", std::to_string(drive_sense), "+1 or -1");
  }

  Eigen::Vector3d line_of_action(const System &system, const MeshLayout &mesh) { return frame(system, mesh).n; }

  std::vector<PointLoad> mesh_loads(const System &system, const MeshLayout &mesh, const std::vector<double> &z,
                                    const std::vector<double> &dz, const std::vector<double> &w)
  {
    const Frame f = frame(system, mesh);
    if (z.size() != w.size() || z.size() != dz.size())
      throw InputError("mesh line load", std::to_string(w.size()) + " values",
                       "one per face position (" + std::to_string(z.size()) + ")");
    std::vector<PointLoad> out;
    for (std::size_t k = 0; k < z.size(); ++k)
      {
        if (!(z[k] >= 0 && z[k] <= mesh.face_width * (1 + 1e-12)))
          throw InputError("mesh face position", mm_text(z[k]), "0 to " + mm_text(mesh.face_width));
        if (!std::isfinite(w[k]) || !std::isfinite(dz[k]))
          throw InputError("mesh line load", to_string_g(w[k]) + " N/m", "finite values");
        const double F = w[k] * dz[k];
        const Eigen::Vector3d Fg = F * (f.n + std::tan(mesh.beta_b) * Eigen::Vector3d::UnitZ());
        // The pitch point from each axis (in the transverse plane).
        const Eigen::Vector3d rp = f.r1 * f.e, rg = -f.r2 * f.e;
        PointLoad g, p;
        g.shaft = mesh.gear_shaft, g.z = mesh.gear_face_start + z[k], g.force = Fg, g.moment = rg.cross(Fg);
        p.shaft = mesh.pinion_shaft, p.z = mesh.pinion_face_start + z[k], p.force = -Fg, p.moment = rp.cross(-Fg);
        out.push_back(g), out.push_back(p);
      }
    return out;
  }

  std::vector<double> mesh_approach(const System &system, const Solution &solution, const MeshLayout &mesh,
                                    const std::vector<double> &z)
  {
    const Frame f = frame(system, mesh);
    const Eigen::Vector3d rp = f.r1 * f.e, rg = -f.r2 * f.e;
    std::vector<double> out;
    for (const double zk : z)
      {
        const auto up = solution.along(system, mesh.pinion_shaft, mesh.pinion_face_start + zk);
        const auto ug = solution.along(system, mesh.gear_shaft, mesh.gear_face_start + zk);
        const Eigen::Vector3d dp = up.head<3>() + Eigen::Vector3d(up.tail<3>()).cross(rp);
        const Eigen::Vector3d dg = ug.head<3>() + Eigen::Vector3d(ug.tail<3>()).cross(rg);
        out.push_back((dp - dg).dot(f.n));
      }
    return out;
  }

  std::vector<Eigen::Vector2d> mesh_axes_offset(const System &system, const Solution &solution,
                                                const MeshLayout &mesh, const std::vector<double> &z)
  {
    const Frame f = frame(system, mesh);
    const Eigen::Vector3d t(-f.e.y(), f.e.x(), 0); // z x e, whatever the drive sense
    std::vector<Eigen::Vector2d> out;
    for (const double zk : z)
      {
        const auto up = solution.along(system, mesh.pinion_shaft, mesh.pinion_face_start + zk);
        const auto ug = solution.along(system, mesh.gear_shaft, mesh.gear_face_start + zk);
        const Eigen::Vector3d d = Eigen::Vector3d(ug.head<3>()) - Eigen::Vector3d(up.head<3>());
        out.emplace_back(d.dot(f.e), d.dot(t));
      }
    return out;
  }
} // namespace gearfem::shafts
