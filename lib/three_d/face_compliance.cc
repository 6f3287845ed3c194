#include "three_d/face_compliance.h"

#include "base/errors.h"
#include "base/progress.h"
#include "fem/tooth_load.h"
#include "mesh/domain.h"
#include "mesh/triangulation.h"
#include "three_d/solid_body.h"

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/numerics/vector_tools.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

namespace gearfem::three_d
{
  void FaceOptions::validate() const
  {
    require_greater("3-D/Face width", face_width, 0.0, "m");
    if (slices < 1 || slices > 200)
      throw InputError("3-D/Slices", std::to_string(slices), "1 to 200");
    if (layers_per_slice < 1 || layers_per_slice * slices > 400)
      throw InputError("3-D/Layers per slice", std::to_string(layers_per_slice),
                       "1 to " + std::to_string(std::max(1, 400 / slices)) + " (at most 400 layers)");
    if (degree != 1 && degree != 2)
      throw InputError("3-D/Degree", std::to_string(degree), "1 or 2");
    if (radii < 2 || radii > 50)
      throw InputError("3-D/Flank points", std::to_string(radii), "2 to 50");
    if (!std::isfinite(twist))
      throw InputError("3-D/Twist", to_string_g(twist), "a finite value");
  }

  namespace
  {
    using Sparse = std::vector<std::pair<unsigned, double>>;

    Sparse sparse(const dealii::Vector<double> &f)
    {
      Sparse s;
      for (unsigned i = 0; i < f.size(); ++i)
        if (f[i] != 0)
          s.emplace_back(i, f[i]);
      return s;
    }

    double dot(const Sparse &a, const dealii::Vector<double> &u)
    {
      double s = 0;
      for (const auto &[i, v] : a)
        s += v * u[i];
      return s;
    }

    /// The section on the straight cells of `tria` in 2-D: FE_Q(p)^2, MappingQ1, the plane
    /// model of `m`, thickness t; clamped at the bore and the cuts; UMFPACK.
    class StraightSection
    {
    public:
      StraightSection(const dealii::Triangulation<2> &tria, const fem::Elasticity &m, unsigned p, double t)
        : fe_(dealii::FE_Q<2>(p), 2), dofs_(tria)
      {
        dofs_.distribute_dofs(fe_);
        dealii::DynamicSparsityPattern dsp(dofs_.n_dofs());
        dealii::DoFTools::make_sparsity_pattern(dofs_, dsp);
        sparsity_.copy_from(dsp);
        K_.reinit(sparsity_);
        const double lambda = m.lambda(), mu = m.mu();
        lambda_ = lambda, mu_ = mu;
        const dealii::QGauss<2> quad(p + 1);
        dealii::FEValues<2> fv(mapping_, fe_, quad, dealii::update_gradients | dealii::update_JxW_values);
        const unsigned n = fe_.n_dofs_per_cell();
        std::vector<dealii::types::global_dof_index> idx(n);
        for (const auto &cell : dofs_.active_cell_iterators())
          {
            fv.reinit(cell);
            cell->get_dof_indices(idx);
            for (unsigned q = 0; q < quad.size(); ++q)
              for (unsigned i = 0; i < n; ++i)
                {
                  const unsigned ci = fe_.system_to_component_index(i).first;
                  const auto gi     = fv.shape_grad(i, q);
                  for (unsigned j = 0; j < n; ++j)
                    {
                      const unsigned cj = fe_.system_to_component_index(j).first;
                      const auto gj     = fv.shape_grad(j, q);
                      K_.add(idx[i], idx[j],
                             t * (gi[ci] * gj[cj] * lambda + gi[cj] * gj[ci] * mu + (ci == cj ? gi * gj * mu : 0.0)) *
                               fv.JxW(q));
                    }
                }
          }
        std::map<dealii::types::global_dof_index, double> zero;
        for (const unsigned id : {mesh::boundary::bore, mesh::boundary::cut_cw, mesh::boundary::cut_ccw})
          dealii::VectorTools::interpolate_boundary_values(mapping_, dofs_, dealii::types::boundary_id(id),
                                                           dealii::Functions::ZeroFunction<2>(2), zero);
        fixed_.assign(dofs_.n_dofs(), false);
        for (const auto &kv : zero)
          fixed_[kv.first] = true;
        double diag = 0;
        for (unsigned r = 0; r < K_.m(); ++r)
          diag += K_.diag_element(r) / double(K_.m());
        for (unsigned r = 0; r < K_.m(); ++r)
          for (auto it = K_.begin(r); it != K_.end(r); ++it)
            if (fixed_[r] || fixed_[it->column()])
              it->value() = r == it->column() ? diag : 0.0;
        solver_.initialize(K_);
      }

      dealii::Vector<double> point_force(const mesh::Vec2 &x, const mesh::Vec2 &force) const
      {
        const auto found = dealii::GridTools::find_active_cell_around_point(mapping_, dofs_, dealii::Point<2>(x.x(), x.y()));
        const dealii::Quadrature<2> at(dealii::GeometryInfo<2>::project_to_unit_cell(found.second));
        dealii::FEValues<2> fv(mapping_, fe_, at, dealii::update_values);
        fv.reinit(found.first);
        std::vector<dealii::types::global_dof_index> idx(fe_.n_dofs_per_cell());
        found.first->get_dof_indices(idx);
        dealii::Vector<double> f(dofs_.n_dofs());
        for (unsigned i = 0; i < idx.size(); ++i)
          f[idx[i]] += fv.shape_value(i, 0) * force[int(fe_.system_to_component_index(i).first)];
        return f;
      }

      /// d . sigma . d at x as a functional of the displacement (plane model's lambda).
      Sparse stress_functional(const mesh::Vec2 &x, const mesh::Vec2 &d) const
      {
        const auto found = dealii::GridTools::find_active_cell_around_point(mapping_, dofs_, dealii::Point<2>(x.x(), x.y()));
        const dealii::Quadrature<2> at(dealii::GeometryInfo<2>::project_to_unit_cell(found.second));
        dealii::FEValues<2> fv(mapping_, fe_, at, dealii::update_gradients);
        fv.reinit(found.first);
        std::vector<dealii::types::global_dof_index> idx(fe_.n_dofs_per_cell());
        found.first->get_dof_indices(idx);
        Sparse out;
        for (unsigned i = 0; i < idx.size(); ++i)
          {
            const unsigned c = fe_.system_to_component_index(i).first;
            const auto g     = fv.shape_grad_component(i, 0, c);
            out.emplace_back(unsigned(idx[i]), lambda_ * g[c] + 2 * mu_ * d[int(c)] * (g[0] * d.x() + g[1] * d.y()));
          }
        return out;
      }

      dealii::Vector<double> solve(dealii::Vector<double> f) const
      {
        for (unsigned i = 0; i < f.size(); ++i)
          if (fixed_[i])
            f[i] = 0;
        solver_.solve(f);
        return f;
      }

    private:
      dealii::MappingQ1<2> mapping_;
      dealii::FESystem<2> fe_;
      dealii::DoFHandler<2> dofs_;
      dealii::SparsityPattern sparsity_;
      dealii::SparseMatrix<double> K_;
      std::vector<bool> fixed_;
      dealii::SparseDirectUMFPACK solver_;
      double lambda_ = 0, mu_ = 0;
    };

    /// The closest point to x on the boundary edges of `mesh` with id `id` (straight chords).
    mesh::Vec2 on_edges(const mesh::MeshData &mesh, unsigned id, const mesh::Vec2 &x)
    {
      double best = std::numeric_limits<double>::infinity();
      mesh::Vec2 out = x;
      for (const auto &e : mesh.boundary_edges)
        {
          if (e.boundary_id != id)
            continue;
          const mesh::Vec2 a = mesh.vertices[e.v0], b = mesh.vertices[e.v1];
          const double t      = std::clamp((x - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
          const mesh::Vec2 p  = a + t * (b - a);
          if ((p - x).norm() < best)
            best = (p - x).norm(), out = p;
        }
      if (!std::isfinite(best))
        throw SolverError("3-D face: the section mesh has no drive flank on tooth 0");
      return out;
    }
  } // namespace

  struct FaceCompliance::Impl
  {
    FaceOptions o;
    std::vector<double> r;        ///< grid radii
    std::vector<mesh::Vec2> x, n; ///< in-plane load points (on the chords) and outward normals
    mesh::MeshData mesh;
    dealii::Triangulation<2> tria;
    std::unique_ptr<SolidBody> body;
    std::vector<Sparse> f3; ///< strip loads, index j * R + a
    Eigen::MatrixXd T3, T2;
    /// Points inside the tension-side (drive) fillet of tooth 0 and their tangents; the fillet's
    /// tangential stress [Pa/N] at point p in slice i under strip (a, j): S3(p N + i, j R + a);
    /// in the section, S2(p, a).
    std::vector<mesh::Vec2> fx, ft;
    Eigen::MatrixXd S3, S2;
    double seconds = 0;
    int R() const { return int(r.size()); }

    /// Strip load of slice j at grid point a (unit transverse force).
    dealii::Vector<double> strip(int a, int j) const
    {
      dealii::Vector<double> f(body->n_dofs());
      const double dz = o.face_width / o.slices, h = dz / o.layers_per_slice;
      const dealii::QGauss<1> g(o.degree + 1);
      const mesh::Vec2 xa = x[std::size_t(a)], na = n[std::size_t(a)];
      // The helicoid's normal: transverse part n, axial part -twist (n . J x), J x = (-x_y, x_x).
      const double nz = -o.twist * (na.x() * -xa.y() + na.y() * xa.x());
      for (int l = 0; l < o.layers_per_slice; ++l)
        for (unsigned q = 0; q < g.size(); ++q)
          {
            const double z = j * dz + (l + g.point(q)[0]) * h, c = std::cos(o.twist * (z - 0.5 * o.face_width)),
                         s = std::sin(o.twist * (z - 0.5 * o.face_width));
            const auto rot = [&](const mesh::Vec2 &v) { return mesh::Vec2(c * v.x() - s * v.y(), s * v.x() + c * v.y()); };
            // Just inside the body: the point finder needs the point in a cell, and between
            // the layers of a twisted body the helix through x bulges past the straight cells
            // by its sagitta r (twist h)^2 / 8.
            const double sag   = xa.norm() * std::pow(o.twist * h, 2) / 8;
            const mesh::Vec2 p = rot(xa - (1e-9 + 4 * sag) * na), d = rot(na);
            Tensor3 force;
            force[0] = -d.x(), force[1] = -d.y(), force[2] = -nz;
            force *= g.weight(q) * h / dz;
            body->add_point_force(Point3(p.x(), p.y(), z), force, f);
          }
      return f;
    }

    /// Linear weights of r on the grid: (a, w_a), (a + 1, w_a+1), held at the ends.
    std::pair<int, double> weight(double rr) const
    {
      const double t = std::clamp((rr - r.front()) / (r.back() - r.front()), 0.0, 1.0) * (R() - 1);
      const int a    = std::min(int(t), R() - 2);
      return {a, t - a};
    }
  };

  FaceCompliance::FaceCompliance(const geometry::ToothProfile &tooth, const mesh::GearMeshParameters &mp,
                                 const fem::Elasticity &material, const FaceOptions &options, std::ostream *progress)
    : impl_(std::make_unique<Impl>())
  {
    const auto t0 = std::chrono::steady_clock::now();
    Impl &m       = *impl_;
    m.o           = options;
    m.o.validate();
    if (mp.model != mesh::GearMeshParameters::Model::sector)
      throw InputError("3-D/Mesh", "full gear", "a sector (the loaded tooth in its middle)");
    m.mesh = mesh::mesh_gear(tooth, mp);
    mesh::create_triangulation(m.mesh, m.tria, mesh::InteriorManifold::none);
    ExtrusionOptions eo;
    eo.face_width = m.o.face_width, eo.layers = m.o.slices * m.o.layers_per_slice, eo.degree = m.o.degree;
    eo.twist      = m.o.twist;
    m.body        = std::make_unique<SolidBody>(m.tria, material, eo);
    for (const unsigned id : {mesh::boundary::bore, mesh::boundary::cut_cw, mesh::boundary::cut_ccw})
      m.body->constrain(dealii::types::boundary_id(id));
    m.body->assemble_and_factorize();

    // The grid over the drive flank of tooth 0.
    double lo = std::numeric_limits<double>::infinity(), hi = 0;
    for (const int i : tooth.flank_segments(geometry::Side::drive))
      for (const double t : {tooth.segments()[std::size_t(i)].t0, tooth.segments()[std::size_t(i)].t1})
        {
          const double rr = tooth.segments()[std::size_t(i)].curve->point(t).norm();
          lo = std::min(lo, rr), hi = std::max(hi, rr);
        }
    const unsigned flank = mesh::boundary::tooth_id(0, mesh::boundary::flank_drive);
    for (int a = 0; a < m.o.radii; ++a)
      {
        const double rr    = lo + (hi - lo) * a / (m.o.radii - 1);
        const auto [p, nn] = fem::flank_point_and_normal(tooth, 0, true, rr);
        m.r.push_back(rr), m.x.push_back(on_edges(m.mesh, flank, p)), m.n.push_back(nn);
      }

    // The fillet: the middle of each of its chords, moved a hundredth of the way to the centre
    // of its cell (the point finder needs a point inside).
    const unsigned fillet = mesh::boundary::tooth_id(0, mesh::boundary::fillet_drive);
    for (const auto &e : m.mesh.boundary_edges)
      {
        if (e.boundary_id != fillet)
          continue;
        const mesh::Vec2 a = m.mesh.vertices[e.v0], b = m.mesh.vertices[e.v1], mid = 0.5 * (a + b);
        for (const auto &c : m.mesh.cells)
          if (std::count(c.begin(), c.end(), e.v0) && std::count(c.begin(), c.end(), e.v1))
            {
              mesh::Vec2 centre = mesh::Vec2::Zero();
              for (const unsigned v : c)
                centre += 0.25 * m.mesh.vertices[v];
              m.fx.push_back(mid + 0.01 * (centre - mid)), m.ft.push_back((b - a).normalized());
              break;
            }
      }
    if (m.fx.empty())
      throw SolverError("3-D face: the section mesh has no drive fillet on tooth 0");
    const int P = int(m.fx.size());
    const int R = m.R(), N = m.o.slices, n = R * N;
    std::vector<Sparse> g3;
    const double dz = m.o.face_width / N;
    for (int p = 0; p < P; ++p)
      for (int i = 0; i < N; ++i)
        {
          const double z = (i + 0.5) * dz, w = m.o.twist * (z - 0.5 * m.o.face_width);
          const double c = std::cos(w), sn = std::sin(w);
          const mesh::Vec2 x = m.fx[std::size_t(p)], t = m.ft[std::size_t(p)];
          Tensor3 d;
          d[0] = c * t.x() - sn * t.y(), d[1] = sn * t.x() + c * t.y();
          g3.push_back(m.body->stress_functional(Point3(c * x.x() - sn * x.y(), sn * x.x() + c * x.y(), z), d));
        }
    m.S3.resize(P * N, n);
    Progress bar(progress, std::size_t(n), "3-D face (z " + std::to_string(tooth.teeth()) + ")");
    for (int j = 0; j < N; ++j)
      for (int a = 0; a < R; ++a)
        m.f3.push_back(sparse(m.strip(a, j)));
    // The strips' displacements in blocks of right-hand sides (one MUMPS solve each).
    m.T3.resize(n, n);
    const std::size_t nd = m.body->n_dofs();
    const int block      = 32;
    for (int k0 = 0; k0 < n; k0 += block)
      {
        const int k = std::min(block, n - k0);
        std::vector<double> U(nd * std::size_t(k), 0.0);
        for (int c = 0; c < k; ++c)
          for (const auto &[i, v] : m.f3[std::size_t(k0 + c)])
            U[std::size_t(c) * nd + i] = v;
        m.body->solve_block(U, unsigned(k));
        for (int c = 0; c < k; ++c)
          for (int l = 0; l < n; ++l)
            {
              double s = 0;
              for (const auto &[i, v] : m.f3[std::size_t(l)])
                s += v * U[std::size_t(c) * nd + i];
              m.T3(l, k0 + c) = s;
            }
        for (int c = 0; c < k; ++c)
          for (int l = 0; l < P * N; ++l)
            {
              double s = 0;
              for (const auto &[i, v] : g3[std::size_t(l)])
                s += v * U[std::size_t(c) * nd + i];
              m.S3(l, k0 + c) = s;
            }
        bar.step(std::size_t(k0 + k));
      }
    m.T3 = 0.5 * (m.T3 + m.T3.transpose()).eval();

    fem::Elasticity plane = material;
    const StraightSection section(m.tria, plane, m.o.degree, m.o.face_width / N);
    std::vector<Sparse> f2;
    for (int a = 0; a < R; ++a)
      f2.push_back(sparse(section.point_force(m.x[std::size_t(a)] - 1e-9 * m.n[std::size_t(a)], -m.n[std::size_t(a)])));
    std::vector<Sparse> g2;
    for (int p = 0; p < P; ++p)
      g2.push_back(section.stress_functional(m.fx[std::size_t(p)], m.ft[std::size_t(p)]));
    m.T2.resize(R, R);
    m.S2.resize(P, R);
    for (int a = 0; a < R; ++a)
      {
        dealii::Vector<double> f(section.point_force(m.x[std::size_t(a)] - 1e-9 * m.n[std::size_t(a)], -m.n[std::size_t(a)]));
        const auto u = section.solve(f);
        for (int b = 0; b < R; ++b)
          m.T2(b, a) = dot(f2[std::size_t(b)], u);
        for (int p = 0; p < P; ++p)
          m.S2(p, a) = dot(g2[std::size_t(p)], u);
      }
    m.T2      = 0.5 * (m.T2 + m.T2.transpose()).eval();
    m.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }

  FaceCompliance::~FaceCompliance() = default;

  double FaceCompliance::solid(int i, double r_i, int j, double r_j) const
  {
    const Impl &m = *impl_;
    const int R   = m.R();
    const auto [a, wa] = m.weight(r_i);
    const auto [b, wb] = m.weight(r_j);
    const double wi[2] = {1 - wa, wa}, wj[2] = {1 - wb, wb};
    double c = 0;
    for (int s = 0; s < 2; ++s)
      for (int t = 0; t < 2; ++t)
        c += wi[s] * wj[t] * m.T3(i * R + a + s, j * R + b + t);
    return c;
  }

  double FaceCompliance::section(double r_i, double r_j) const
  {
    const Impl &m = *impl_;
    const auto [a, wa] = m.weight(r_i);
    const auto [b, wb] = m.weight(r_j);
    const double wi[2] = {1 - wa, wa}, wj[2] = {1 - wb, wb};
    double c = 0;
    for (int s = 0; s < 2; ++s)
      for (int t = 0; t < 2; ++t)
        c += wi[s] * wj[t] * m.T2(a + s, b + t);
    return c;
  }

  Eigen::MatrixXd FaceCompliance::correction(const std::vector<double> &r) const
  {
    const int N = impl_->o.slices;
    if (int(r.size()) != N)
      throw InputError("3-D face radii", std::to_string(r.size()), std::to_string(N) + " (one per slice)");
    Eigen::MatrixXd C(N, N);
    for (int i = 0; i < N; ++i)
      for (int j = 0; j <= i; ++j)
        C(i, j) = C(j, i) = solid(i, r[std::size_t(i)], j, r[std::size_t(j)]);
    for (int i = 0; i < N; ++i)
      C(i, i) -= section(r[std::size_t(i)], r[std::size_t(i)]);
    return C;
  }

  std::vector<double> FaceCompliance::section_load(const std::vector<double> &force, const std::vector<double> &r) const
  {
    const Impl &m = *impl_;
    const int N = m.o.slices, R = m.R(), P = int(m.fx.size());
    if (int(force.size()) != N || int(r.size()) != N)
      throw InputError("3-D face forces", std::to_string(force.size()), std::to_string(N) + " (one per slice)");
    std::vector<double> out(std::size_t(N), 0.0);
    for (int i = 0; i < N; ++i)
      {
        double s3 = 0, s2 = 0;
        const auto [a, w] = m.weight(r[std::size_t(i)]);
        for (int p = 0; p < P; ++p)
          {
            double s = 0;
            for (int j = 0; j < N; ++j)
              {
                const auto [b, v] = m.weight(r[std::size_t(j)]);
                s += force[std::size_t(j)] * ((1 - v) * m.S3(p * N + i, j * R + b) + v * m.S3(p * N + i, j * R + b + 1));
              }
            s3 = std::max(s3, s);
            s2 = std::max(s2, (1 - w) * m.S2(p, a) + w * m.S2(p, a + 1));
          }
        out[std::size_t(i)] = s2 > 0 ? std::max(0.0, s3 / s2) : 0.0;
      }
    return out;
  }

  void FaceCompliance::write_vtu(const std::vector<double> &force, const std::vector<double> &r,
                                 const std::filesystem::path &file, double scale) const
  {
    const Impl &m = *impl_;
    const int N   = m.o.slices;
    if (int(force.size()) != N || int(r.size()) != N)
      throw InputError("3-D face forces", std::to_string(force.size()), std::to_string(N) + " (one per slice)");
    dealii::Vector<double> f(m.body->n_dofs());
    for (int j = 0; j < N; ++j)
      {
        const auto [a, w] = m.weight(r[std::size_t(j)]);
        for (int s = 0; s < 2; ++s)
          for (const auto &[i, v] : m.f3[std::size_t(j * m.R() + a + s)])
            f[i] += force[std::size_t(j)] * (s ? w : 1 - w) * v;
      }
    m.body->write_vtu(m.body->solve(f), file, scale);
  }

  const std::vector<double> &FaceCompliance::radii() const { return impl_->r; }
  const FaceOptions &FaceCompliance::options() const { return impl_->o; }
  unsigned int FaceCompliance::n_dofs() const { return impl_->body->n_dofs(); }
  unsigned int FaceCompliance::n_cells() const { return impl_->body->n_cells(); }
  double FaceCompliance::seconds() const { return impl_->seconds; }
} // namespace gearfem::three_d
