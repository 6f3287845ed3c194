#include "three_d/solid_body.h"

#include "base/atomic_file.h"
#include "base/errors.h"

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/vector_tools.h>

#include <algorithm>
#include <cmath>

namespace gearfem::three_d
{
  void ExtrusionOptions::validate() const
  {
    require_greater("3-D/Face width", face_width, 0.0, "m");
    if (layers < 1 || layers > 400)
      throw InputError("3-D/Layers", std::to_string(layers), "1 to 400");
    if (degree != 1 && degree != 2)
      throw InputError("3-D/Degree", std::to_string(degree), "1 or 2");
  }

  SolidBody::SolidBody(const dealii::Triangulation<2> &section, const fem::Elasticity &material,
                       const ExtrusionOptions &options)
    : material_(material), options_(options), fe_(dealii::FE_Q<3>(options.degree), 3)
  {
    options_.validate();
    material_.validate();
    if (section.n_levels() > 1)
      throw InputError("3-D section", std::to_string(section.n_levels() - 1) + " refinements",
                       "an unrefined section mesh (deal.II extrudes coarse meshes only)");
    // deal.II counts the planes of vertices: layers + 1 of them.
    dealii::GridGenerator::extrude_triangulation(section, unsigned(options_.layers + 1), options_.face_width, tria_);
    if (options_.twist != 0)
      dealii::GridTools::transform(
        [w = options_.twist, m = 0.5 * options_.face_width](const Point3 &p) {
          const double c = std::cos(w * (p[2] - m)), s = std::sin(w * (p[2] - m));
          return Point3(c * p[0] - s * p[1], s * p[0] + c * p[1], p[2]);
        },
        tria_);
    // The end faces take the two ids after the largest of the section (deal.II's rule).
    dealii::types::boundary_id top = 0;
    for (const auto id : section.get_boundary_ids())
      top = std::max(top, id);
    end_start_ = dealii::types::boundary_id(top + 1), end_finish_ = dealii::types::boundary_id(top + 2);
    dof_handler_.reinit(tria_);
    dof_handler_.distribute_dofs(fe_);
  }

  SolidBody::~SolidBody() = default;

  void SolidBody::constrain(dealii::types::boundary_id id) { clamped_.insert(id); }

  void SolidBody::assemble_and_factorize()
  {
    if (clamped_.empty())
      throw SolverError("3-D body: no clamped boundary (the stiffness is singular)");
    dealii::DynamicSparsityPattern dsp(dof_handler_.n_dofs());
    dealii::DoFTools::make_sparsity_pattern(dof_handler_, dsp);
    sparsity_.copy_from(dsp);
    stiffness_.reinit(sparsity_);
    const double E = material_.youngs_modulus, nu = material_.poisson_ratio;
    const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
    const dealii::QGauss<3> quad(options_.degree + 1);
    dealii::FEValues<3> fv(fe_, quad, dealii::update_gradients | dealii::update_JxW_values);
    const unsigned n = fe_.n_dofs_per_cell();
    dealii::FullMatrix<double> Ke(n, n);
    std::vector<dealii::types::global_dof_index> dofs(n);
    for (const auto &cell : dof_handler_.active_cell_iterators())
      {
        fv.reinit(cell);
        Ke = 0;
        for (unsigned q = 0; q < quad.size(); ++q)
          for (unsigned i = 0; i < n; ++i)
            {
              const unsigned ci = fe_.system_to_component_index(i).first;
              const auto gi     = fv.shape_grad(i, q);
              for (unsigned j = 0; j < n; ++j)
                {
                  const unsigned cj = fe_.system_to_component_index(j).first;
                  const auto gj     = fv.shape_grad(j, q);
                  // lambda div div + mu (grad + grad^T) : grad, componentwise (step-8).
                  Ke(i, j) += (gi[ci] * gj[cj] * lambda + gi[cj] * gj[ci] * mu + (ci == cj ? gi * gj * mu : 0.0)) *
                              fv.JxW(q);
                }
            }
        cell->get_dof_indices(dofs);
        for (unsigned i = 0; i < n; ++i)
          for (unsigned j = 0; j < n; ++j)
            stiffness_.add(dofs[i], dofs[j], Ke(i, j));
      }
    // Clamped DoFs: identity rows and columns (homogeneous data, the system stays symmetric).
    std::map<dealii::types::global_dof_index, double> zero;
    for (const auto id : clamped_)
      dealii::VectorTools::interpolate_boundary_values(dealii::MappingQ1<3>(), dof_handler_, id,
                                                       dealii::Functions::ZeroFunction<3>(3), zero);
    if (zero.empty())
      throw SolverError("3-D body: the clamped boundaries hold no DoF");
    constrained_.assign(dof_handler_.n_dofs(), false);
    for (const auto &[d, v] : zero)
      constrained_[d] = v == 0.0; // all zero: homogeneous data
    double diag = 0; // a typical diagonal entry keeps the eliminated rows well scaled
    for (unsigned r = 0; r < stiffness_.m(); ++r)
      diag += std::abs(stiffness_.diag_element(r)) / double(stiffness_.m());
    for (unsigned r = 0; r < stiffness_.m(); ++r)
      for (auto it = stiffness_.begin(r); it != stiffness_.end(r); ++it)
        if (constrained_[r] || constrained_[it->column()])
          it->value() = (r == it->column()) ? diag : 0.0;
    solver_.factorize(stiffness_, fem::SolverKind::mumps);
  }

  dealii::Vector<double> SolidBody::traction_load(const Tensor3 &t, const std::set<dealii::types::boundary_id> &ids,
                                                  const std::function<bool(const Point3 &)> &where) const
  {
    const dealii::QGauss<2> quad(options_.degree + 1);
    dealii::FEFaceValues<3> fv(fe_, quad, dealii::update_values | dealii::update_JxW_values);
    const unsigned n = fe_.n_dofs_per_cell();
    dealii::Vector<double> f(dof_handler_.n_dofs());
    std::vector<dealii::types::global_dof_index> dofs(n);
    for (const auto &cell : dof_handler_.active_cell_iterators())
      for (unsigned k = 0; k < dealii::GeometryInfo<3>::faces_per_cell; ++k)
        {
          const auto face = cell->face(k);
          if (!face->at_boundary() || !ids.count(face->boundary_id()) || (where && !where(face->center())))
            continue;
          fv.reinit(cell, k);
          cell->get_dof_indices(dofs);
          for (unsigned q = 0; q < quad.size(); ++q)
            for (unsigned i = 0; i < n; ++i)
              f[dofs[i]] += fv.shape_value(i, q) * t[fe_.system_to_component_index(i).first] * fv.JxW(q);
        }
    return f;
  }

  void SolidBody::add_point_force(const Point3 &x, const Tensor3 &force, dealii::Vector<double> &f) const
  {
    const dealii::MappingQ1<3> mapping;
    const auto found = dealii::GridTools::find_active_cell_around_point(mapping, dof_handler_, x);
    if (found.first.state() != dealii::IteratorState::valid)
      throw SolverError("3-D body: the point (" + to_string_g(x[0]) + ", " + to_string_g(x[1]) + ", " +
                        to_string_g(x[2]) + ") m lies in no cell");
    const dealii::Quadrature<3> at(dealii::GeometryInfo<3>::project_to_unit_cell(found.second));
    dealii::FEValues<3> fv(mapping, fe_, at, dealii::update_values);
    fv.reinit(found.first);
    std::vector<dealii::types::global_dof_index> dofs(fe_.n_dofs_per_cell());
    found.first->get_dof_indices(dofs);
    for (unsigned i = 0; i < dofs.size(); ++i)
      f[dofs[i]] += fv.shape_value(i, 0) * force[fe_.system_to_component_index(i).first];
  }

  std::vector<std::pair<unsigned, double>> SolidBody::stress_functional(const Point3 &x, const Tensor3 &d) const
  {
    const dealii::MappingQ1<3> mapping;
    const auto found = dealii::GridTools::find_active_cell_around_point(mapping, dof_handler_, x);
    if (found.first.state() != dealii::IteratorState::valid)
      throw SolverError("3-D body: the point (" + to_string_g(x[0]) + ", " + to_string_g(x[1]) + ", " +
                        to_string_g(x[2]) + ") m lies in no cell");
    const dealii::Quadrature<3> at(dealii::GeometryInfo<3>::project_to_unit_cell(found.second));
    dealii::FEValues<3> fv(mapping, fe_, at, dealii::update_gradients);
    fv.reinit(found.first);
    std::vector<dealii::types::global_dof_index> dofs(fe_.n_dofs_per_cell());
    found.first->get_dof_indices(dofs);
    const double E = material_.youngs_modulus, nu = material_.poisson_ratio;
    const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
    std::vector<std::pair<unsigned, double>> out;
    for (unsigned i = 0; i < dofs.size(); ++i)
      {
        // Shape function i is e_c phi: div = d_c phi, d . sym grad . d = d_c (grad phi . d).
        const unsigned c = fe_.system_to_component_index(i).first;
        const auto g     = fv.shape_grad_component(i, 0, c);
        out.emplace_back(unsigned(dofs[i]), lambda * g[c] + 2 * mu * d[c] * (g * d));
      }
    return out;
  }

  dealii::Vector<double> SolidBody::solve(const dealii::Vector<double> &f) const
  {
    if (f.size() != dof_handler_.n_dofs())
      throw InputError("3-D load vector", std::to_string(f.size()) + " entries", std::to_string(n_dofs()));
    dealii::Vector<double> b(f), u(f.size());
    for (unsigned i = 0; i < b.size(); ++i)
      if (constrained_[i])
        b[i] = 0;
    solver_.solve(b, u);
    return u;
  }

  void SolidBody::solve_block(std::vector<double> &columns, unsigned k) const
  {
    const std::size_t n = dof_handler_.n_dofs();
    if (columns.size() != n * k)
      throw InputError("3-D load block", std::to_string(columns.size()) + " entries", std::to_string(n * k));
    for (unsigned c = 0; c < k; ++c)
      for (std::size_t i = 0; i < n; ++i)
        if (constrained_[i])
          columns[c * n + i] = 0;
    solver_.solve_block(columns, k);
  }

  Tensor3 SolidBody::displacement_at(const dealii::Vector<double> &u, const Point3 &x) const
  {
    dealii::Vector<double> v(3);
    dealii::VectorTools::point_value(dealii::MappingQ1<3>(), dof_handler_, u, x, v);
    Tensor3 out;
    for (unsigned c = 0; c < 3; ++c)
      out[c] = v[c];
    return out;
  }

  dealii::SymmetricTensor<2, 3> SolidBody::stress_at(const dealii::Vector<double> &u, const Point3 &x) const
  {
    std::vector<dealii::Tensor<1, 3>> grad(3);
    dealii::VectorTools::point_gradient(dealii::MappingQ1<3>(), dof_handler_, u, x, grad);
    const double E = material_.youngs_modulus, nu = material_.poisson_ratio;
    const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
    dealii::SymmetricTensor<2, 3> eps;
    for (unsigned i = 0; i < 3; ++i)
      for (unsigned j = i; j < 3; ++j)
        eps[i][j] = 0.5 * (grad[i][j] + grad[j][i]);
    return lambda * dealii::trace(eps) * dealii::unit_symmetric_tensor<3>() + 2 * mu * eps;
  }

  Tensor3 SolidBody::resultant(const dealii::Vector<double> &f) const
  {
    Tensor3 r;
    // The component of each DoF from the FE system's numbering, cell by cell (each DoF once).
    std::vector<bool> seen(f.size(), false);
    std::vector<dealii::types::global_dof_index> dofs(fe_.n_dofs_per_cell());
    for (const auto &cell : dof_handler_.active_cell_iterators())
      {
        cell->get_dof_indices(dofs);
        for (unsigned i = 0; i < dofs.size(); ++i)
          if (!seen[dofs[i]])
            seen[dofs[i]] = true, r[fe_.system_to_component_index(i).first] += f[dofs[i]];
      }
    return r;
  }

  void SolidBody::write_vtu(const dealii::Vector<double> &u, const std::filesystem::path &file, double scale) const
  {
    if (u.size() != dof_handler_.n_dofs())
      throw InputError("3-D displacement", std::to_string(u.size()) + " entries", std::to_string(n_dofs()));
    dealii::Vector<double> shown(u);
    shown *= scale;
    std::vector<dealii::DataComponentInterpretation::DataComponentInterpretation> vec(
      3, dealii::DataComponentInterpretation::component_is_part_of_vector);
    dealii::DataOut<3> out;
    out.attach_dof_handler(dof_handler_);
    out.add_data_vector(u, std::vector<std::string>(3, "u"), dealii::DataOut<3>::type_dof_data, vec);
    out.add_data_vector(shown, std::vector<std::string>(3, "shown"), dealii::DataOut<3>::type_dof_data, vec);
    out.build_patches();
    AtomicOutputFile f(file);
    out.write_vtu(f.stream());
    f.commit();
  }
} // namespace gearfem::three_d
