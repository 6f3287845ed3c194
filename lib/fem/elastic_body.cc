// ElasticBody: setup, WorkStream assembly, Dirichlet elimination, solves, reactions and
// stress recovery.
#include "fem/elastic_body.h"
#include "fem/stress_peak.h"

#include "base/errors.h"

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/work_stream.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/tria_accessor.h>
#include <deal.II/grid/tria_iterator.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/numerics/vector_tools_point_value.h>

#include <algorithm>
#include <map>
#include <chrono>
#include <cmath>

namespace gearfem::fem
{
  namespace
  {
    using Clock = std::chrono::steady_clock;
    double seconds_since(Clock::time_point t0)
    {
      return std::chrono::duration<double>(Clock::now() - t0).count();
    }

    struct ScratchData
    {
      ScratchData(const dealii::Mapping<2> &mapping, const dealii::FiniteElement<2> &fe,
                  const dealii::Quadrature<2> &q)
        : fe_values(mapping, fe, q, dealii::update_gradients | dealii::update_JxW_values)
      {}
      ScratchData(const ScratchData &o)
        : fe_values(o.fe_values.get_mapping(), o.fe_values.get_fe(), o.fe_values.get_quadrature(),
                    o.fe_values.get_update_flags())
      {}
      dealii::FEValues<2> fe_values;
    };
    struct CopyData
    {
      dealii::FullMatrix<double> matrix;
      std::vector<dealii::types::global_dof_index> dofs;
    };
  } // namespace

  void FeOptions::validate() const
  {
    if (degree != 1 && degree != 2)
      throw InputError("Finite elements/Degree", std::to_string(degree), "{1, 2}");
    if (refinements > 6)
      throw InputError("Finite elements/Global refinements", std::to_string(refinements), "[0, 6]");
  }

  ElasticBody::ElasticBody(const mesh::MeshData &mesh, const Elasticity &material,
                           const FeOptions &options)
    : mesh_(mesh)
    , material_(material)
    , options_(options)
    , fe_((options.validate(), dealii::FE_Q<2>(options.degree)), 2)
  {
    material_.validate();
    mesh::create_triangulation(mesh_, tria_, options_.interior);
    if (options_.refinements > 0)
      tria_.refine_global(options_.refinements);
    mapping_ = std::make_unique<dealii::MappingQCache<2>>(options_.degree);
    mapping_->initialize(dealii::MappingQ<2>(options_.degree), tria_);
    dof_handler_.reinit(tria_);
    dof_handler_.distribute_dofs(fe_);

    const unsigned int n = dof_handler_.n_dofs();
    dof_points_.assign(n, Point2());
    dof_component_.assign(n, 0);
    dealii::Quadrature<2> support(fe_.get_unit_support_points());
    dealii::FEValues<2> fev(*mapping_, fe_, support, dealii::update_quadrature_points);
    std::vector<dealii::types::global_dof_index> dofs(fe_.dofs_per_cell);
    for (const auto &cell : dof_handler_.active_cell_iterators())
      {
        fev.reinit(cell);
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < dofs.size(); ++i)
          {
            dof_points_[dofs[i]]    = fev.quadrature_point(i);
            dof_component_[dofs[i]] = fe_.system_to_component_index(i).first;
          }
      }
    constrained_.assign(n, false);
  }

  ElasticBody::~ElasticBody() { dof_handler_.clear(); }

  void ElasticBody::constrain(dealii::types::boundary_id id, bool x, bool y)
  {
    dirichlet_[id] = {x, y};
  }

  void ElasticBody::assemble_and_factorize()
  {
    auto t0 = Clock::now();
    const unsigned int n = dof_handler_.n_dofs();
    constrained_.assign(n, false);
    for (const auto &[id, comp] : dirichlet_)
      {
        const dealii::ComponentMask mask(std::vector<bool>{comp.first, comp.second});
        const dealii::IndexSet s = dealii::DoFTools::extract_boundary_dofs(dof_handler_, mask, {id});
        for (const auto i : s)
          constrained_[i] = true;
      }

    dealii::DynamicSparsityPattern dsp(n, n);
    dealii::DoFTools::make_sparsity_pattern(dof_handler_, dsp);
    sparsity_.copy_from(dsp);
    stiffness_.reinit(sparsity_);

    const double lambda = material_.lambda(), mu = material_.mu(), b = material_.thickness;
    const dealii::FEValuesExtractors::Vector disp(0);
    const dealii::QGauss<2> quadrature(options_.degree + 1);
    auto worker = [&](const dealii::DoFHandler<2>::active_cell_iterator &cell, ScratchData &s,
                      CopyData &c) {
      s.fe_values.reinit(cell);
      const unsigned int nd = fe_.dofs_per_cell;
      c.matrix.reinit(nd, nd);
      c.dofs.resize(nd);
      cell->get_dof_indices(c.dofs);
      std::vector<dealii::SymmetricTensor<2, 2>> eps(nd);
      std::vector<double> div(nd);
      for (unsigned int q = 0; q < s.fe_values.n_quadrature_points; ++q)
        {
          for (unsigned int i = 0; i < nd; ++i)
            {
              eps[i] = s.fe_values[disp].symmetric_gradient(i, q);
              div[i] = dealii::trace(eps[i]);
            }
          const double w = b * s.fe_values.JxW(q);
          for (unsigned int i = 0; i < nd; ++i)
            for (unsigned int j = i; j < nd; ++j)
              c.matrix(i, j) += (lambda * div[i] * div[j] + 2.0 * mu * (eps[i] * eps[j])) * w;
        }
      for (unsigned int i = 0; i < nd; ++i)
        for (unsigned int j = 0; j < i; ++j)
          c.matrix(i, j) = c.matrix(j, i);
    };
    auto copier = [&](const CopyData &c) { stiffness_.add(c.dofs, c.matrix); };
    dealii::WorkStream::run(dof_handler_.begin_active(), dof_handler_.end(), worker, copier,
                            ScratchData(*mapping_, fe_, quadrature), CopyData());

    // Dirichlet elimination: zero constrained rows and columns, scaled identity on the
    // diagonal, so that the factors serve any prescribed values.
    double diag_sum = 0;
    for (unsigned int i = 0; i < n; ++i)
      diag_sum += stiffness_.diag_element(i);
    diagonal_scale_ = diag_sum / std::max(1u, n);
    reduced_.reinit(sparsity_);
    reduced_.copy_from(stiffness_);
    for (unsigned int i = 0; i < n; ++i)
      for (auto it = reduced_.begin(i); it != reduced_.end(i); ++it)
        if (constrained_[i] || constrained_[it->column()])
          it->value() = (it->column() == i) ? diagonal_scale_ : 0.0;
    t_assemble_ = seconds_since(t0);

    t0 = Clock::now();
    if (std::none_of(constrained_.begin(), constrained_.end(), [](bool c) { return c; }))
      throw SolverError("the body has no Dirichlet boundary: its stiffness matrix is singular");
    solver_.factorize(reduced_, options_.solver, options_.umfpack_max_dofs);
    t_factorize_ = seconds_since(t0);
  }

  dealii::Vector<double>
  ElasticBody::traction_load(const VectorFunction &traction,
                             const std::set<dealii::types::boundary_id> &ids,
                             const std::function<bool(const Point2 &)> &where) const
  {
    dealii::Vector<double> f(dof_handler_.n_dofs());
    const dealii::QGauss<1> q(options_.degree + 2);
    dealii::FEFaceValues<2> fv(*mapping_, fe_, q,
                               dealii::update_values | dealii::update_quadrature_points |
                                 dealii::update_JxW_values);
    std::vector<dealii::types::global_dof_index> dofs(fe_.dofs_per_cell);
    for (const auto &cell : dof_handler_.active_cell_iterators())
      for (const auto face : cell->face_indices())
        {
          if (!cell->at_boundary(face) || ids.count(cell->face(face)->boundary_id()) == 0)
            continue;
          fv.reinit(cell, face);
          cell->get_dof_indices(dofs);
          for (unsigned int k = 0; k < q.size(); ++k)
            {
              const Point2 &x = fv.quadrature_point(k);
              if (where && !where(x))
                continue;
              const Tensor2 t = traction(x);
              for (unsigned int i = 0; i < fe_.dofs_per_cell; ++i)
                {
                  const unsigned int c = fe_.system_to_component_index(i).first;
                  f[dofs[i]] += t[c] * fv.shape_value(i, k) * fv.JxW(k) * material_.thickness;
                }
            }
        }
    return f;
  }

  dealii::Vector<double> ElasticBody::solve(const dealii::Vector<double> &f,
                                            const VectorFunction &g) const
  {
    const unsigned int n = dof_handler_.n_dofs();
    if (f.size() != n)
      throw SolverError("load vector size does not match the body's DoFs");
    dealii::Vector<double> ud(n), rhs(n), u(n);
    if (g)
      for (unsigned int i = 0; i < n; ++i)
        if (constrained_[i])
          ud[i] = g(dof_points_[i])[dof_component_[i]];
    stiffness_.vmult(rhs, ud);
    rhs.sadd(-1.0, 1.0, f);
    for (unsigned int i = 0; i < n; ++i)
      if (constrained_[i])
        rhs[i] = diagonal_scale_ * ud[i];
    solver_.solve(rhs, u);
    for (unsigned int i = 0; i < n; ++i)
      if (!std::isfinite(u[i]))
        throw SolverError("the linear solver returned a non-finite displacement");
    return u;
  }

  std::vector<std::vector<double>> ElasticBody::compliance_columns(
    const std::vector<unsigned int> &dofs, const std::vector<std::vector<unsigned int>> &rows) const
  {
    std::vector<std::vector<double>> out = solver_.inverse_entries(dofs, rows);
    for (std::size_t j = 0; j < dofs.size(); ++j)
      for (std::size_t i = 0; i < rows[j].size(); ++i)
        {
          double &v = out[j][i];
          if (!std::isfinite(v))
            throw SolverError("the linear solver returned a non-finite compliance");
          if (constrained_.at(dofs[j]) || constrained_[rows[j][i]])
            v = 0.0;
        }
    return out;
  }

  dealii::Vector<double> ElasticBody::reactions(const dealii::Vector<double> &u,
                                                const dealii::Vector<double> &f) const
  {
    dealii::Vector<double> r(u.size());
    stiffness_.vmult(r, u);
    r -= f;
    return r;
  }

  Tensor2 ElasticBody::displacement_at(const dealii::Vector<double> &u, const Point2 &x) const
  {
    dealii::Vector<double> v(2);
    dealii::VectorTools::point_value(*mapping_, dof_handler_, u, x, v);
    Tensor2 t;
    t[0] = v[0];
    t[1] = v[1];
    return t;
  }

  double ElasticBody::moment(const dealii::Vector<double> &F, const Point2 &c) const
  {
    double m = 0;
    for (unsigned int i = 0; i < F.size(); ++i)
      m += dof_component_[i] == 0 ? -(dof_points_[i][1] - c[1]) * F[i] :
                                    (dof_points_[i][0] - c[0]) * F[i];
    return m;
  }

  std::vector<std::pair<unsigned int, double>> ElasticBody::reaction_moment_functional(const Point2 &c) const
  {
    std::map<unsigned int, double> row;
    for (unsigned int i = 0; i < stiffness_.m(); ++i)
      {
        if (!constrained_[i])
          continue;
        const double arm = dof_component_[i] == 0 ? -(dof_points_[i][1] - c[1]) : dof_points_[i][0] - c[0];
        for (auto it = stiffness_.begin(i); it != stiffness_.end(i); ++it)
          if (!constrained_[it->column()] && it->value() != 0)
            row[static_cast<unsigned int>(it->column())] += arm * it->value();
      }
    return {row.begin(), row.end()};
  }

  Tensor2 ElasticBody::resultant(const dealii::Vector<double> &F) const
  {
    Tensor2 r;
    for (unsigned int i = 0; i < F.size(); ++i)
      r[dof_component_[i]] += F[i];
    return r;
  }

  StressPoint ElasticBody::stress_at(const std::vector<dealii::Tensor<1, 2>> &g,
                                     const Point2 &x) const
  {
    StressPoint s;
    s.x           = x;
    const auto sg = material_.stress(g[0][0], g[1][1], 0.5 * (g[0][1] + g[1][0]));
    s.sxx = sg[0], s.syy = sg[1], s.sxy = sg[2];
    s.szz          = material_.stress_zz(s.sxx, s.syy);
    const auto p   = principal_stresses(s.sxx, s.syy, s.sxy);
    s.s1           = p[0];
    s.s2           = p[1];
    s.von_mises    = von_mises(s.sxx, s.syy, s.sxy, s.szz);
    return s;
  }

  std::vector<StressPoint> ElasticBody::quadrature_stresses(const dealii::Vector<double> &u) const
  {
    std::vector<StressPoint> out;
    const dealii::QGauss<2> q(options_.degree + 1);
    dealii::FEValues<2> fv(*mapping_, fe_, q, dealii::update_gradients | dealii::update_quadrature_points);
    std::vector<std::vector<dealii::Tensor<1, 2>>> grads(q.size(), std::vector<dealii::Tensor<1, 2>>(2));
    for (const auto &cell : dof_handler_.active_cell_iterators())
      {
        fv.reinit(cell);
        fv.get_function_gradients(u, grads);
        for (unsigned int k = 0; k < q.size(); ++k)
          out.push_back(stress_at(grads[k], fv.quadrature_point(k)));
      }
    return out;
  }

  std::vector<int> ElasticBody::pieces_with_id(dealii::types::boundary_id id) const
  {
    std::vector<int> p;
    for (std::size_t i = 0; i < mesh_.pieces.size(); ++i)
      if (mesh_.pieces[i].boundary_id == id)
        p.push_back(int(i));
    return p;
  }

  dealii::Quadrature<1> ElasticBody::boundary_samples(unsigned int per_face)
  {
    std::vector<dealii::Point<1>> pts;
    for (unsigned int k = 0; k < per_face; ++k)
      pts.emplace_back((k + 0.5) / per_face);
    return dealii::Quadrature<1>(pts, std::vector<double>(per_face, 1.0 / per_face));
  }

  void ElasticBody::locate_on_pieces(BoundaryStressSample &s, const std::vector<int> &pieces) const
  {
    const mesh::Vec2 x(s.stress.x[0], s.stress.x[1]);
    double best = 1e300;
    for (const int p : pieces)
      {
        const auto &piece = mesh_.pieces[p];
        const double t    = piece.curve.closest_parameter(x, piece.t0, piece.t1);
        const double d    = (piece.curve.point(t) - x).norm();
        if (d < best)
          best = d, s.piece = p, s.parameter = t;
      }
  }

  std::vector<std::size_t> ElasticBody::order_along_outline(std::vector<BoundaryStressSample> &out) const
  {
    // Order along the outline: by piece, then by the direction of travel of the piece.
    std::vector<std::size_t> perm(out.size());
    for (std::size_t i = 0; i < perm.size(); ++i)
      perm[i] = i;
    std::stable_sort(perm.begin(), perm.end(), [&](std::size_t i, std::size_t j) {
      const auto &a = out[i], &b = out[j];
      if (a.piece != b.piece)
        return a.piece < b.piece;
      const auto &p = mesh_.pieces[a.piece];
      return (p.t1 >= p.t0) ? a.parameter < b.parameter : a.parameter > b.parameter;
    });
    std::vector<BoundaryStressSample> sorted;
    sorted.reserve(out.size());
    for (const std::size_t i : perm)
      sorted.push_back(out[i]);
    out.swap(sorted);
    double s = 0;
    for (std::size_t i = 0; i < out.size(); ++i)
      {
        if (i == 0)
          {
            const auto &p = mesh_.pieces[out[0].piece];
            const mesh::Vec2 x0(out[0].stress.x[0], out[0].stress.x[1]);
            s = (x0 - p.start()).norm();
          }
        else
          s += out[i].stress.x.distance(out[i - 1].stress.x);
        out[i].arc_length = s;
      }
    return perm;
  }

  std::vector<BoundaryStressSample>
  ElasticBody::boundary_stress(const dealii::Vector<double> &u, dealii::types::boundary_id id,
                               unsigned int per_face) const
  {
    const std::vector<int> pieces = pieces_with_id(id);
    if (pieces.empty())
      throw InputError("boundary id", std::to_string(id), "an id of this body's mesh");
    const dealii::Quadrature<1> q = boundary_samples(per_face);
    dealii::FEFaceValues<2> fv(*mapping_, fe_, q, dealii::update_gradients | dealii::update_quadrature_points);
    std::vector<std::vector<dealii::Tensor<1, 2>>> grads(q.size(), std::vector<dealii::Tensor<1, 2>>(2));
    std::vector<BoundaryStressSample> out;
    for (const auto &cell : dof_handler_.active_cell_iterators())
      for (const auto face : cell->face_indices())
        if (cell->at_boundary(face) && cell->face(face)->boundary_id() == id)
          {
            fv.reinit(cell, face);
            fv.get_function_gradients(u, grads);
            for (unsigned int k = 0; k < q.size(); ++k)
              {
                BoundaryStressSample s;
                s.stress = stress_at(grads[k], fv.quadrature_point(k));
                locate_on_pieces(s, pieces);
                out.push_back(s);
              }
          }
    order_along_outline(out);
    return out;
  }

  BoundaryStressFunctionals ElasticBody::boundary_stress_functionals(dealii::types::boundary_id id,
                                                                     unsigned int per_face) const
  {
    const std::vector<int> pieces = pieces_with_id(id);
    if (pieces.empty())
      throw InputError("boundary id", std::to_string(id), "an id of this body's mesh");
    const dealii::Quadrature<1> q = boundary_samples(per_face);
    dealii::FEFaceValues<2> fv(*mapping_, fe_, q, dealii::update_gradients | dealii::update_quadrature_points);
    std::vector<dealii::types::global_dof_index> dofs(fe_.dofs_per_cell);
    // The stress of a unit strain component: sigma is linear in (exx, eyy, exy).
    const std::array<std::array<double, 3>, 3> unit = {material_.stress(1, 0, 0), material_.stress(0, 1, 0),
                                                       material_.stress(0, 0, 1)};
    BoundaryStressFunctionals out;
    std::vector<std::vector<std::pair<unsigned int, double>>> rows;
    for (const auto &cell : dof_handler_.active_cell_iterators())
      for (const auto face : cell->face_indices())
        if (cell->at_boundary(face) && cell->face(face)->boundary_id() == id)
          {
            fv.reinit(cell, face);
            cell->get_dof_indices(dofs);
            for (unsigned int k = 0; k < q.size(); ++k)
              {
                BoundaryStressSample s;
                s.stress.x = fv.quadrature_point(k);
                locate_on_pieces(s, pieces);
                out.samples.push_back(s);
                std::array<std::vector<std::pair<unsigned int, double>>, 3> r;
                for (unsigned int i = 0; i < fe_.dofs_per_cell; ++i)
                  {
                    const unsigned int c = fe_.system_to_component_index(i).first;
                    const auto g         = fv.shape_grad_component(i, k, c);
                    // Strain of this shape function: exx = g0 (c = 0), eyy = g1 (c = 1),
                    // exy = (du_x/dy + du_y/dx) / 2.
                    const double e[3] = {c == 0 ? g[0] : 0.0, c == 1 ? g[1] : 0.0, 0.5 * (c == 0 ? g[1] : g[0])};
                    for (int comp = 0; comp < 3; ++comp)
                      {
                        const double v = unit[0][comp] * e[0] + unit[1][comp] * e[1] + unit[2][comp] * e[2];
                        if (v != 0)
                          r[comp].emplace_back(static_cast<unsigned int>(dofs[i]), v);
                      }
                  }
                for (auto &x : r)
                  rows.push_back(std::move(x));
              }
          }
    const auto perm = order_along_outline(out.samples);
    out.rows.reserve(rows.size());
    for (const std::size_t i : perm)
      for (int comp = 0; comp < 3; ++comp)
        out.rows.push_back(std::move(rows[3 * i + comp]));
    return out;
  }

  StressPoint ElasticBody::stress_point(double sxx, double syy, double sxy, const Point2 &x) const
  {
    StressPoint s;
    s.x = x, s.sxx = sxx, s.syy = syy, s.sxy = sxy;
    s.szz          = material_.stress_zz(sxx, syy);
    const auto p   = principal_stresses(sxx, syy, sxy);
    s.s1 = p[0], s.s2 = p[1];
    s.von_mises = von_mises(sxx, syy, sxy, s.szz);
    return s;
  }

  StressPeak ElasticBody::peak_principal_stress(const dealii::Vector<double> &u,
                                                dealii::types::boundary_id id,
                                                unsigned int per_face) const
  {
    const auto samples = boundary_stress(u, id, per_face);
    StressPeak peak;
    if (samples.empty())
      return peak;
    std::vector<double> arc, s1;
    for (const auto &s : samples)
      arc.push_back(s.arc_length), s1.push_back(s.stress.s1);
    const auto pk   = fitted_peak(arc, s1, per_face);
    const auto &s   = samples[pk.index];
    peak.value      = pk.value;
    peak.arc_length = s.arc_length;
    peak.x          = s.stress.x;
    peak.radius     = s.stress.x.norm();
    peak.angle      = std::atan2(s.stress.x[1], s.stress.x[0]);
    return peak;
  }

  ErrorNorms ElasticBody::errors(
    const dealii::Vector<double> &u, const VectorFunction &u_exact,
    const std::function<dealii::SymmetricTensor<2, 2>(const Point2 &)> &stress_exact) const
  {
    ErrorNorms e;
    const dealii::QGauss<2> q(options_.degree + 2);
    dealii::FEValues<2> fv(*mapping_, fe_, q,
                           dealii::update_values | dealii::update_gradients |
                             dealii::update_quadrature_points | dealii::update_JxW_values);
    std::vector<dealii::Vector<double>> vals(q.size(), dealii::Vector<double>(2));
    std::vector<std::vector<dealii::Tensor<1, 2>>> grads(q.size(), std::vector<dealii::Tensor<1, 2>>(2));
    const double lambda = material_.lambda(), mu = material_.mu();
    for (const auto &cell : dof_handler_.active_cell_iterators())
      {
        fv.reinit(cell);
        fv.get_function_values(u, vals);
        fv.get_function_gradients(u, grads);
        for (unsigned int k = 0; k < q.size(); ++k)
          {
            const Point2 &x  = fv.quadrature_point(k);
            const Tensor2 ue = u_exact(x);
            const double w   = fv.JxW(k);
            e.l2_displacement += (std::pow(ue[0] - vals[k][0], 2) + std::pow(ue[1] - vals[k][1], 2)) * w;
            const StressPoint sh = stress_at(grads[k], x);
            const auto se        = stress_exact(x);
            const double dxx = se[0][0] - sh.sxx, dyy = se[1][1] - sh.syy, dxy = se[0][1] - sh.sxy;
            e.l2_stress += (dxx * dxx + dyy * dyy + 2 * dxy * dxy) * w;
            // Energy norm of the error: strain from the stress difference (inverse law).
            const double tr = (dxx + dyy) / (2.0 * (lambda + mu));
            const double exx = (dxx - lambda * tr) / (2 * mu), eyy = (dyy - lambda * tr) / (2 * mu),
                         exy = dxy / (2 * mu);
            e.h1_displacement += (dxx * exx + dyy * eyy + 2 * dxy * exy) * w;
          }
      }
    e.l2_displacement = std::sqrt(e.l2_displacement);
    e.l2_stress       = std::sqrt(e.l2_stress);
    e.h1_displacement = std::sqrt(e.h1_displacement);
    return e;
  }

  std::vector<BoundaryNode>
  ElasticBody::boundary_nodes(const std::set<dealii::types::boundary_id> &ids) const
  {
    std::vector<BoundaryNode> out;
    std::vector<bool> seen(dof_handler_.n_dofs(), false);
    std::vector<dealii::types::global_dof_index> fd(fe_.dofs_per_face);
    for (const auto &cell : dof_handler_.active_cell_iterators())
      for (const auto face : cell->face_indices())
        {
          if (!cell->at_boundary(face))
            continue;
          const auto id = cell->face(face)->boundary_id();
          if (ids.count(id) == 0)
            continue;
          cell->face(face)->get_dof_indices(fd);
          const auto pieces = pieces_with_id(id);
          for (unsigned int i = 0; i < fd.size(); ++i)
            {
              if (seen[fd[i]] || fe_.face_system_to_component_index(i).first != 0)
                continue;
              seen[fd[i]] = true;
              BoundaryNode nd;
              nd.x           = dof_points_[fd[i]];
              nd.dof_x       = fd[i];
              nd.boundary_id = id;
              // The y DoF of the same node is the face DoF with the same support point.
              for (unsigned int j = 0; j < fd.size(); ++j)
                if (fe_.face_system_to_component_index(j).first == 1 &&
                    dof_points_[fd[j]].distance(nd.x) < 1e-14)
                  nd.dof_y = fd[j];
              double best = 1e300;
              const mesh::Vec2 x(nd.x[0], nd.x[1]);
              for (const int p : pieces)
                {
                  const auto &piece = mesh_.pieces[p];
                  const double t    = piece.curve.closest_parameter(x, piece.t0, piece.t1);
                  const double d    = (piece.curve.point(t) - x).norm();
                  if (d < best)
                    best = d, nd.piece = p, nd.parameter = t;
                }
              out.push_back(nd);
            }
        }
    return out;
  }
} // namespace gearfem::fem
