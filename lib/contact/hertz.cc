// The Hertz two-disc case: graded disc meshes, translation drive, comparison.
#include "contact/hertz.h"
#include "base/units.h"

#include "base/errors.h"
#include "mesh/domain.h"

#include <Eigen/Dense>

#include <chrono>
#include <cmath>

namespace gearfem::contact
{
  namespace
  {
    using units::pi;

    /// Disc of radius R about the origin with a bore R/4 (id 1, clamped); the outline is
    /// split so that the arc |theta - theta_c| < half_angle has size h_fine (id 5), the rest
    /// h_body (id 4).
    mesh::Domain disc(double R, double theta_c, double half_angle, double h_fine, double h_body)
    {
      mesh::Domain d;
      d.h_body = h_body;
      d.growth = 1.2;
      mesh::Loop outer, inner;
      mesh::BoundaryPiece fine;
      fine.curve       = mesh::ParametricCurve::circle(mesh::Vec2(0, 0), R);
      fine.t0          = theta_c - half_angle;
      fine.t1          = theta_c + half_angle;
      fine.boundary_id = 5;
      fine.size        = h_fine;
      mesh::BoundaryPiece rest = fine;
      rest.t0          = theta_c + half_angle;
      rest.t1          = theta_c - half_angle + 2 * pi;
      rest.boundary_id = 4;
      rest.size        = h_body;
      // Split the long arc so that every piece is well below a half circle.
      const int n = 4;
      const double t0 = rest.t0, t1 = rest.t1;
      outer.pieces.push_back(fine);
      for (int k = 0; k < n; ++k)
        {
          mesh::BoundaryPiece p = rest;
          p.t0 = t0 + (t1 - t0) * k / n;
          p.t1 = t0 + (t1 - t0) * (k + 1) / n;
          outer.pieces.push_back(p);
        }
      for (int k = 0; k < 4; ++k)
        {
          mesh::BoundaryPiece i;
          i.curve       = mesh::ParametricCurve::circle(mesh::Vec2(0, 0), R / 4);
          i.t0          = -k * pi / 2;
          i.t1          = -(k + 1) * pi / 2;
          i.boundary_id = mesh::boundary::bore;
          i.size        = h_body;
          inner.pieces.push_back(i);
        }
      d.loops = {outer, inner};
      return d;
    }
  } // namespace

  std::pair<double, double> hertz_closed_form(const HertzCase &c)
  {
    const bool strain  = c.model == fem::PlaneModel::plane_strain;
    const double t2    = c.thickness2 > 0 ? c.thickness2 : c.thickness;
    const double inv_Et = (strain ? 1 - c.nu1 * c.nu1 : 1.0) / (c.E1 * c.thickness) +
                          (strain ? 1 - c.nu2 * c.nu2 : 1.0) / (c.E2 * t2); // 1/(E* t) [m/N]
    const double R     = 1.0 / (1.0 / c.R1 + 1.0 / c.R2);
    const double a     = std::sqrt(4 * c.force * R * inv_Et / pi);
    return {a, 2 * c.force / (pi * a * std::min(c.thickness, t2))};
  }

  std::array<double, 3> fit_ellipse(const std::vector<std::pair<double, double>> &samples)
  {
    std::vector<std::pair<double, double>> s;
    for (const auto &v : samples)
      if (v.second > 0)
        s.push_back(v);
    if (s.size() < 3)
      return {0, 0, 0};
    double scale = 0;
    for (const auto &v : s)
      scale = std::max(scale, std::abs(v.first));
    scale = scale > 0 ? scale : 1.0;
    Eigen::MatrixXd A(s.size(), 3);
    Eigen::VectorXd b(s.size());
    for (std::size_t i = 0; i < s.size(); ++i)
      {
        const double x = s[i].first / scale;
        A(i, 0) = 1, A(i, 1) = x, A(i, 2) = x * x;
        b[i]    = s[i].second * s[i].second;
      }
    const Eigen::Vector3d c = A.colPivHouseholderQr().solve(b);
    if (!(c[2] < 0))
      return {0, 0, 0};
    const double s0 = -c[1] / (2 * c[2]);
    const double p2 = c[0] - c[1] * c[1] / (4 * c[2]);
    if (!(p2 > 0))
      return {0, 0, 0};
    return {std::sqrt(-p2 / c[2]) * scale, std::sqrt(p2), s0 * scale};
  }

  HertzResult solve_hertz(const HertzCase &c)
  {
    const auto t0 = std::chrono::steady_clock::now();
    HertzResult r;
    std::tie(r.a_exact, r.p0_exact) = hertz_closed_form(c);
    const double h  = c.h_contact > 0 ? c.h_contact : r.a_exact / 8;
    r.h_contact     = h;
    const double hb = std::max(c.h_body, h);
    // The fine arc spans +-4 a (the patch and its neighbourhood).
    const double half1 = 4 * r.a_exact / c.R1, half2 = 4 * r.a_exact / c.R2;
    const auto m1 = mesh::mesh_domain(disc(c.R1, pi / 2, half1, h, hb));
    const auto m2 = mesh::mesh_domain(disc(c.R2, -pi / 2, half2, h, hb));
    fem::Elasticity e1, e2;
    e1.youngs_modulus = c.E1, e1.poisson_ratio = c.nu1, e1.thickness = c.thickness, e1.model = c.model;
    e2.youngs_modulus = c.E2, e2.poisson_ratio = c.nu2, e2.thickness = c.thickness2 > 0 ? c.thickness2 : c.thickness, e2.model = c.model;
    fem::FeOptions fe;
    fe.degree = c.degree;
    fem::ElasticBody b1(m1, e1, fe), b2(m2, e2, fe);
    b1.constrain(mesh::boundary::bore);
    b2.constrain(mesh::boundary::bore);
    b1.assemble_and_factorize();
    b2.assemble_and_factorize();
    r.n_dofs = b1.n_dofs() + b2.n_dofs();

    ContactSurface s1(b1, {5}), s2(b2, {5});
    ContactOptions o;
    o.method          = c.method;
    o.penalty_factor  = c.penalty_factor;
    o.slave           = c.slave != 0 ? c.slave : (c.E2 < c.E1 ? 2 : 1);
    o.search_distance = std::max(2 * r.a_exact * r.a_exact * (1 / c.R1 + 1 / c.R2), 4 * h);
    Drive drive;
    drive.kind      = Drive::Kind::translation;
    drive.direction = Vec2(0, 1);
    TwoBodyContact solver(s1, s2, o, drive);
    Scene scene;
    scene.placement[0] = {Vec2(0, 0), 0.0};
    scene.placement[1] = {Vec2(0, c.R1 + c.R2), 0.0};
    r.solution = solver.solve(scene, Control::load, c.force);
    // Conservation: the nodal contact forces of body 1 sum to (0, -F), those of body 2 to
    // (0, +F) (both bodies are placed unrotated, so body and pair frames coincide).
    double fy[2] = {0, 0};
    for (int b = 0; b < 2; ++b)
      for (const auto &[dof, f] : r.solution.forces[b])
        if ((b == 0 ? b1 : b2).dof_components()[dof] == 1)
          fy[b] += f;
    r.force_balance = std::max(std::abs(fy[0] + c.force), std::abs(fy[1] - c.force)) / c.force;
    for (const auto &p : r.solution.points)
      {
        if (p.force > 0)
          {
            r.profile.emplace_back(p.x.x(), p.pressure);
            r.p0_nodal = std::max(r.p0_nodal, p.pressure);
            ++r.n_active;
          }
      }
    std::sort(r.profile.begin(), r.profile.end());
    const auto fit = fit_ellipse(r.profile);
    r.a_fit = fit[0], r.p0_fit = fit[1];
    double e2sum = 0;
    for (const auto &[s, p] : r.profile)
      {
        const double pe = r.p0_exact * std::sqrt(std::max(0.0, 1 - s * s / (r.a_exact * r.a_exact)));
        e2sum += (p - pe) * (p - pe);
      }
    r.profile_error = r.profile.empty() ? 1.0 : std::sqrt(e2sum / r.profile.size()) / r.p0_exact;
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return r;
  }
} // namespace gearfem::contact
