#include "shafts/shaft.h"

#include "base/errors.h"

#include <Eigen/Cholesky>

#include <algorithm>
#include <cmath>
#include <map>

namespace gearfem::shafts
{
  namespace
  {
    constexpr double tol = 1e-12; // relative position tolerance along a shaft

    std::string shaft_name(const System &s, int i)
    {
      return i >= 0 && i < int(s.shafts.size()) && !s.shafts[std::size_t(i)].name.empty() ?
               s.shafts[std::size_t(i)].name :
               "shaft " + std::to_string(i);
    }

    /// The nodes of every shaft: its segment ends, stations, and every position a bearing, a
    /// load or a coupling names, each element split to max_element.
    struct Layout
    {
      std::vector<std::vector<double>> z; // per shaft, sorted
      std::vector<int> first;             // per shaft, its first global node
      int n_nodes = 0;
      int node(int shaft, double zz, const std::string &what) const
      {
        const auto &v = z[std::size_t(shaft)];
        const double scale = std::max(1.0, v.back());
        for (std::size_t i = 0; i < v.size(); ++i)
          if (std::abs(v[i] - zz) <= tol * scale)
            return first[std::size_t(shaft)] + int(i);
        throw InputError(what, mm_text(zz), "a position on the shaft");
      }
    };

    void check_on(const System &s, int shaft, double z, const std::string &what)
    {
      if (shaft < 0 || shaft >= int(s.shafts.size()))
        throw InputError(what, "shaft " + std::to_string(shaft),
                         "a shaft of the system (0 to " + std::to_string(int(s.shafts.size()) - 1) + ")");
      const double L = s.shafts[std::size_t(shaft)].length();
      if (!(z >= -tol * L && z <= L * (1 + tol)))
        throw InputError(what, mm_text(z), "0 to " + mm_text(L) + " along " + shaft_name(s, shaft));
    }

    Layout layout(const System &s, const std::vector<PointLoad> &loads)
    {
      Layout l;
      std::vector<std::vector<double>> at(s.shafts.size());
      for (const auto &b : s.bearings)
        check_on(s, b.shaft, b.z, "bearing " + b.name), at[std::size_t(b.shaft)].push_back(b.z);
      for (const auto &p : loads)
        check_on(s, p.shaft, p.z, "load position"), at[std::size_t(p.shaft)].push_back(p.z);
      for (const auto &c : s.couplings)
        {
          check_on(s, c.shaft_a, c.z_a, "coupling position"), at[std::size_t(c.shaft_a)].push_back(c.z_a);
          check_on(s, c.shaft_b, c.z_b, "coupling position"), at[std::size_t(c.shaft_b)].push_back(c.z_b);
        }
      for (std::size_t i = 0; i < s.shafts.size(); ++i)
        {
          const auto &sh = s.shafts[i];
          std::vector<double> z = {0.0};
          double acc = 0;
          for (const auto &seg : sh.segments)
            z.push_back(acc += seg.length);
          z.insert(z.end(), sh.stations.begin(), sh.stations.end());
          z.insert(z.end(), at[i].begin(), at[i].end());
          std::sort(z.begin(), z.end());
          std::vector<double> u;
          for (const double v : z)
            if (u.empty() || v - u.back() > tol * std::max(1.0, acc))
              u.push_back(std::clamp(v, 0.0, acc));
          if (sh.max_element > 0)
            {
              std::vector<double> fine = {u.front()};
              for (std::size_t k = 1; k < u.size(); ++k)
                {
                  const int n = std::max(1, int(std::ceil((u[k] - u[k - 1]) / sh.max_element - 1e-9)));
                  for (int j = 1; j <= n; ++j)
                    fine.push_back(u[k - 1] + (u[k] - u[k - 1]) * j / n);
                }
              u = fine;
            }
          l.first.push_back(l.n_nodes);
          l.n_nodes += int(u.size());
          l.z.push_back(std::move(u));
        }
      return l;
    }

    /// The segment of shaft `sh` that holds axial position z (the element's middle).
    const Segment &segment_at(const Shaft &sh, double z)
    {
      double acc = 0;
      for (const auto &seg : sh.segments)
        {
          acc += seg.length;
          if (z <= acc)
            return seg;
        }
      return sh.segments.back();
    }

    /// Timoshenko interpolation of the bending in one plane (w, theta = dw/dz sense) at xi in
    /// [0, 1] of an element of length L with shear parameter phi (Friedman & Kosmatka, Comput.
    /// Struct. 47, 1993: the shape functions of the exact end-loaded solution).
    std::pair<double, double> bend(double xi, double L, double phi, double w1, double t1, double w2, double t2)
    {
      const double d = 1 + phi, x2 = xi * xi, x3 = x2 * xi;
      const double N1 = (2 * x3 - 3 * x2 - phi * xi + 1 + phi) / d;
      const double N2 = L * (x3 - (2 + phi / 2) * x2 + (1 + phi / 2) * xi) / d;
      const double N3 = (-2 * x3 + 3 * x2 + phi * xi) / d;
      const double N4 = L * (x3 - (1 - phi / 2) * x2 - (phi / 2) * xi) / d;
      const double M1 = 6 * (x2 - xi) / (d * L);
      const double M2 = (3 * x2 - (4 + phi) * xi + 1 + phi) / d;
      const double M3 = -M1;
      const double M4 = (3 * x2 - (2 - phi) * xi) / d;
      return {N1 * w1 + N2 * t1 + N3 * w2 + N4 * t2, M1 * w1 + M2 * t1 + M3 * w2 + M4 * t2};
    }

    double shear_parameter(double L, const Section &s, const ShaftMaterial &m)
    {
      const double G = m.youngs_modulus / (2 * (1 + m.poisson_ratio));
      return 12 * m.youngs_modulus * s.second_moment / (s.shear_coefficient * G * s.area * L * L);
    }
    /// Checks the bearings' springs and housings; the seat node of each bearing on a housing
    /// stiffness (numbered from n_nodes on, which it advances), -1 for the others.
    std::vector<int> seats(const System &system, int &n_nodes)
    {
      std::vector<int> seat(system.bearings.size(), -1);
      for (std::size_t i = 0; i < system.bearings.size(); ++i)
        {
          const auto &b = system.bearings[i];
          for (const double k : {b.radial, b.axial, b.tilting, b.torsional})
            if (!(k >= 0))
              throw InputError("bearing " + b.name + " stiffness", to_string_g(k), ">= 0 (or rigid)");
          if (b.housing.size() > 0)
            {
              if (b.housing.rows() != 6 || b.housing.cols() != 6 || !b.housing.allFinite() ||
                  (b.housing - b.housing.transpose()).norm() > 1e-9 * b.housing.norm())
                throw InputError("bearing " + b.name + " housing", "a " + std::to_string(b.housing.rows()) + "x" +
                                                                      std::to_string(b.housing.cols()) + " matrix",
                                 "a symmetric 6x6 stiffness with finite entries");
              for (const double k : {b.radial, b.axial, b.tilting, b.torsional})
                if (std::isinf(k))
                  throw InputError("bearing " + b.name + " stiffness", "rigid",
                                   "finite springs on a housing stiffness (the housing is the series spring)");
              seat[i] = n_nodes++;
            }
        }
      return seat;
    }

    /// The bearings' reactions on the shafts: -k (u - u_seat) of a spring, and the residual
    /// K u - f at a constrained DoF.
    std::vector<BearingReaction> reactions(const System &system, const Layout &l, const std::vector<int> &seat,
                                           const Eigen::VectorXd &residual, const Eigen::VectorXd &u)
    {
      std::vector<BearingReaction> out;
      for (std::size_t i = 0; i < system.bearings.size(); ++i)
        {
          const auto &b  = system.bearings[i];
          const int node = l.node(b.shaft, b.z, "bearing " + b.name);
          const double k[6] = {b.radial, b.radial, b.axial, b.tilting, b.tilting, b.torsional};
          BearingReaction r;
          r.name = b.name;
          for (int d = 0; d < 6; ++d)
            {
              const int g = 6 * node + d;
              double v    = 0;
              if (std::isinf(k[d]))
                v = residual[g];
              else if (k[d] > 0)
                v = -k[d] * (u[g] - (seat[i] >= 0 ? u[6 * seat[i] + d] : 0.0));
              (d < 3 ? r.force[d] : r.moment[d - 3]) = v;
            }
          out.push_back(r);
        }
      return out;
    }
  } // namespace

  Section section(const Segment &s, double nu)
  {
    Section r;
    const double D = s.outer_diameter, d = s.inner_diameter, m = d / D, m2 = m * m;
    r.area          = M_PI / 4 * (D * D - d * d);
    r.second_moment = M_PI / 64 * (std::pow(D, 4) - std::pow(d, 4));
    r.polar_moment  = 2 * r.second_moment;
    r.shear_coefficient =
      6 * (1 + nu) * (1 + m2) * (1 + m2) / ((7 + 6 * nu) * (1 + m2) * (1 + m2) + (20 + 12 * nu) * m2);
    return r;
  }

  double Shaft::length() const
  {
    double L = 0;
    for (const auto &s : segments)
      L += s.length;
    return L;
  }

  void Shaft::validate() const
  {
    const std::string who = name.empty() ? "shaft" : name;
    if (segments.empty())
      throw InputError(who + " segments", "(none)", "at least one segment");
    for (const auto &s : segments)
      {
        if (!(s.length > 0 && s.length < 1e3))
          throw InputError(who + " segment length", mm_text(s.length), "> 0");
        if (!(s.outer_diameter > 0 && s.outer_diameter < 1e2))
          throw InputError(who + " segment diameter", mm_text(s.outer_diameter), "> 0");
        if (!(s.inner_diameter >= 0 && s.inner_diameter < s.outer_diameter))
          throw InputError(who + " segment bore", mm_text(s.inner_diameter),
                           "0 (solid) to below the outer diameter " + mm_text(s.outer_diameter));
      }
    if (!(material.youngs_modulus > 0 && std::isfinite(material.youngs_modulus)))
      throw InputError(who + " Young's modulus", to_string_g(material.youngs_modulus), "> 0 Pa");
    if (!(material.poisson_ratio > -1 && material.poisson_ratio < 0.5))
      throw InputError(who + " Poisson's ratio", to_string_g(material.poisson_ratio), "-1 to 0.5 (exclusive)");
    for (const double z : stations)
      if (!(z >= 0 && z <= length()))
        throw InputError(who + " station", mm_text(z), "0 to " + mm_text(length()));
    if (!(max_element >= 0))
      throw InputError(who + " element length", mm_text(max_element), ">= 0 (0: no split)");
  }

  Eigen::Matrix<double, 12, 12> element_stiffness(double L, const Section &s, const ShaftMaterial &m)
  {
    Eigen::Matrix<double, 12, 12> K = Eigen::Matrix<double, 12, 12>::Zero();
    const double E = m.youngs_modulus, G = E / (2 * (1 + m.poisson_ratio));
    const double phi = shear_parameter(L, s, m);
    // Bending with w and theta = dw/dz: [w1, t1, w2, t2].
    const double c = E * s.second_moment / ((1 + phi) * L * L * L);
    Eigen::Matrix4d kb;
    kb << 12, 6 * L, -12, 6 * L,                                  //
      6 * L, (4 + phi) * L * L, -6 * L, (2 - phi) * L * L,        //
      -12, -6 * L, 12, -6 * L,                                    //
      6 * L, (2 - phi) * L * L, -6 * L, (4 + phi) * L * L;
    kb *= c;
    // x-z plane: w = u_x, theta = theta_y (du_x/dz = theta_y); y-z plane: w = u_y, theta =
    // -theta_x (du_y/dz = -theta_x).
    const int xz[4] = {ux, ry, 6 + ux, 6 + ry};
    const int yz[4] = {uy, rx, 6 + uy, 6 + rx};
    const double syz[4] = {1, -1, 1, -1};
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        {
          K(xz[i], xz[j]) += kb(i, j);
          K(yz[i], yz[j]) += syz[i] * syz[j] * kb(i, j);
        }
    const double ka = E * s.area / L, kt = G * s.polar_moment / L;
    K(uz, uz) += ka, K(6 + uz, 6 + uz) += ka, K(uz, 6 + uz) -= ka, K(6 + uz, uz) -= ka;
    K(rz, rz) += kt, K(6 + rz, 6 + rz) += kt, K(rz, 6 + rz) -= kt, K(6 + rz, rz) -= kt;
    return K;
  }

  const NodeResult &Solution::at(int shaft, double z) const
  {
    for (const auto &n : nodes)
      if (n.shaft == shaft && std::abs(n.z - z) <= tol * std::max(1.0, std::abs(z)))
        return n;
    throw InputError("shaft position", mm_text(z), "a node of shaft " + std::to_string(shaft));
  }

  Eigen::Matrix<double, 6, 1> Solution::along(const System &system, int shaft, double z) const
  {
    const NodeResult *a = nullptr, *b = nullptr;
    for (const auto &n : nodes)
      if (n.shaft == shaft)
        {
          if (n.z <= z + tol)
            a = &n;
          if (!b && n.z >= z - tol)
            b = &n;
        }
    if (!a || !b)
      throw InputError("shaft position", mm_text(z), "along shaft " + std::to_string(shaft));
    if (a == b || b->z - a->z <= tol)
      return a->u;
    const auto &sh = system.shafts[std::size_t(shaft)];
    const double L = b->z - a->z, xi = (z - a->z) / L;
    const auto &m  = sh.material;
    const double phi = shear_parameter(L, section(segment_at(sh, 0.5 * (a->z + b->z)), m.poisson_ratio), m);
    Eigen::Matrix<double, 6, 1> u;
    const auto [wx, ty] = bend(xi, L, phi, a->u[ux], a->u[ry], b->u[ux], b->u[ry]);
    const auto [wy, mtx] = bend(xi, L, phi, a->u[uy], -a->u[rx], b->u[uy], -b->u[rx]);
    u[ux] = wx, u[ry] = ty, u[uy] = wy, u[rx] = -mtx;
    u[uz] = (1 - xi) * a->u[uz] + xi * b->u[uz];
    u[rz] = (1 - xi) * a->u[rz] + xi * b->u[rz];
    return u;
  }

  Solution solve(const System &system, const std::vector<PointLoad> &loads) { return solve_cases(system, {loads}).front(); }

  std::vector<Solution> solve_cases(const System &system, const std::vector<std::vector<PointLoad>> &cases)
  {
    std::vector<PointLoad> all;
    for (const auto &c : cases)
      all.insert(all.end(), c.begin(), c.end());
    if (system.shafts.empty())
      throw InputError("System shafts", "(none)", "at least one shaft");
    for (const auto &s : system.shafts)
      s.validate();
    const Layout l = layout(system, all);
    // Seat nodes of bearings on a housing stiffness come after the shaft nodes.
    int n_nodes = l.n_nodes;
    const std::vector<int> seat = seats(system, n_nodes);
    const int n = 6 * n_nodes;
    Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n, n);
    for (std::size_t s = 0; s < system.shafts.size(); ++s)
      {
        const auto &sh = system.shafts[s];
        const auto &z  = l.z[s];
        for (std::size_t e = 0; e + 1 < z.size(); ++e)
          {
            const double L  = z[e + 1] - z[e];
            const auto Ke   = element_stiffness(L, section(segment_at(sh, 0.5 * (z[e] + z[e + 1])), sh.material.poisson_ratio),
                                                sh.material);
            const int a     = 6 * (l.first[s] + int(e));
            K.block<12, 12>(a, a) += Ke;
          }
      }
    std::vector<char> fixed(std::size_t(n), 0);
    const auto spring = [&](int i, int j, double k) { // j < 0: to ground
      K(i, i) += k;
      if (j >= 0)
        K(j, j) += k, K(i, j) -= k, K(j, i) -= k;
    };
    for (std::size_t i = 0; i < system.bearings.size(); ++i)
      {
        const auto &b  = system.bearings[i];
        const int node = l.node(b.shaft, b.z, "bearing " + b.name);
        const double k[6] = {b.radial, b.radial, b.axial, b.tilting, b.tilting, b.torsional};
        for (int d = 0; d < 6; ++d)
          {
            if (std::isinf(k[d]))
              fixed[std::size_t(6 * node + d)] = 1;
            else if (k[d] > 0)
              spring(6 * node + d, seat[i] >= 0 ? 6 * seat[i] + d : -1, k[d]);
          }
        if (seat[i] >= 0)
          K.block<6, 6>(6 * seat[i], 6 * seat[i]) += b.housing;
      }
    for (const auto &c : system.couplings)
      {
        const int a = l.node(c.shaft_a, c.z_a, "coupling position"), b = l.node(c.shaft_b, c.z_b, "coupling position");
        // A spring between two points carries no moment of their offset: the joined nodes must
        // coincide (in-line shafts; parallel shafts meet through their gear mesh instead).
        const auto &sa = system.shafts[std::size_t(c.shaft_a)], &sb = system.shafts[std::size_t(c.shaft_b)];
        const Eigen::Vector3d pa(sa.x, sa.y, sa.z0 + c.z_a), pb(sb.x, sb.y, sb.z0 + c.z_b);
        if ((pa - pb).norm() > tol * std::max({1.0, pa.norm(), pb.norm()}))
          throw InputError("coupling position", mm_text((pa - pb).norm()) + " apart",
                           "the same point of both shafts (in-line shafts)");
        for (int d = 0; d < 6; ++d)
          {
            if (!(c.stiffness[std::size_t(d)] >= 0 && std::isfinite(c.stiffness[std::size_t(d)])))
              throw InputError("coupling stiffness", to_string_g(c.stiffness[std::size_t(d)]), ">= 0 and finite");
            if (c.stiffness[std::size_t(d)] > 0)
              spring(6 * a + d, 6 * b + d, c.stiffness[std::size_t(d)]);
          }
      }
    // Rigid supports: eliminate the constrained DoFs (u = 0 there).
    std::vector<int> free;
    for (int i = 0; i < n; ++i)
      if (!fixed[std::size_t(i)])
        free.push_back(i);
    const int m = int(free.size());
    Eigen::MatrixXd Kf(m, m);
    for (int i = 0; i < m; ++i)
      for (int j = 0; j < m; ++j)
        Kf(i, j) = K(free[std::size_t(i)], free[std::size_t(j)]);
    const Eigen::LLT<Eigen::MatrixXd> llt(Kf);
    if (llt.info() != Eigen::Success || !(llt.rcond() > 1e-14))
      throw InputError("System bearings", "a shaft with a free rigid-body motion",
                       "bearings and couplings that hold every shaft radially, axially and in torsion");
    std::vector<Solution> out;
    for (const auto &loads : cases)
      {
        Eigen::VectorXd f = Eigen::VectorXd::Zero(n);
        for (const auto &p : loads)
          {
            if (!p.force.allFinite() || !p.moment.allFinite())
              throw InputError("load", "a non-finite force or moment", "finite values");
            const int node = l.node(p.shaft, p.z, "load position");
            f.segment<3>(6 * node) += p.force;
            f.segment<3>(6 * node + 3) += p.moment;
          }
        Eigen::VectorXd ff(m);
        for (int i = 0; i < m; ++i)
          ff[i] = f[free[std::size_t(i)]];
        const Eigen::VectorXd uf = llt.solve(ff);
        Eigen::VectorXd u = Eigen::VectorXd::Zero(n);
        for (int i = 0; i < m; ++i)
          u[free[std::size_t(i)]] = uf[i];
        if (!u.allFinite())
          throw SolverError("shaft system: a non-finite displacement");
        Solution sol;
        for (std::size_t s = 0; s < system.shafts.size(); ++s)
          for (std::size_t k = 0; k < l.z[s].size(); ++k)
            {
              NodeResult r;
              r.shaft = int(s), r.z = l.z[s][k];
              r.u     = u.segment<6>(6 * (l.first[s] + int(k)));
              sol.nodes.push_back(r);
            }
        sol.reactions = reactions(system, l, seat, K * u - f, u);
        out.push_back(std::move(sol));
      }
    return out;
  }
} // namespace gearfem::shafts
