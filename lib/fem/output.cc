// VTU output of an ElasticBody on the deformed configuration.
#include "base/atomic_file.h"
#include "fem/elastic_body.h"
#include "fem/output.h"

#include <deal.II/base/data_out_base.h>
#include <deal.II/fe/mapping_q_eulerian.h>
#include <deal.II/grid/tria_accessor.h>
#include <deal.II/grid/tria_iterator.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/data_postprocessor.h>

namespace gearfem::fem
{
  namespace
  {
    /// sigma_xx, sigma_yy, sigma_xy, sigma_1, sigma_2, von Mises [MPa] from the gradient.
    class StressPostprocessor : public dealii::DataPostprocessor<2>
    {
    public:
      explicit StressPostprocessor(const Elasticity &m)
        : m_(m)
      {}
      void evaluate_vector_field(const dealii::DataPostprocessorInputs::Vector<2> &in,
                                 std::vector<dealii::Vector<double>> &out) const override
      {
        for (unsigned int k = 0; k < in.solution_gradients.size(); ++k)
          {
            const auto &g = in.solution_gradients[k];
            const auto s  = m_.stress(g[0][0], g[1][1], 0.5 * (g[0][1] + g[1][0]));
            const auto p  = principal_stresses(s[0], s[1], s[2]);
            const double vm = von_mises(s[0], s[1], s[2], m_.stress_zz(s[0], s[1]));
            const double v[6] = {s[0], s[1], s[2], p[0], p[1], vm};
            for (unsigned int j = 0; j < 6; ++j)
              out[k][j] = v[j] / 1e6;
          }
      }
      std::vector<std::string> get_names() const override
      {
        return {"sigma_xx", "sigma_yy", "sigma_xy", "sigma_1", "sigma_2", "von_mises"};
      }
      dealii::UpdateFlags get_needed_update_flags() const override
      {
        return dealii::update_gradients;
      }

    private:
      Elasticity m_;
    };
  } // namespace

  void ElasticBody::write_vtu(const dealii::Vector<double> &u, const std::filesystem::path &file,
                              double scale) const
  {
    dealii::Vector<double> shift(u);
    shift *= scale;
    dealii::MappingQEulerian<2, dealii::Vector<double>> deformed(options_.degree, dof_handler_, shift);
    StressPostprocessor stress(material_);
    dealii::DataOut<2> out;
    out.attach_dof_handler(dof_handler_);
    const std::vector<std::string> names(2, "displacement");
    const std::vector<dealii::DataComponentInterpretation::DataComponentInterpretation> interp(
      2, dealii::DataComponentInterpretation::component_is_part_of_vector);
    dealii::Vector<double> u_mm(u);
    u_mm *= 1e3;
    out.add_data_vector(u_mm, names, dealii::DataOut<2>::type_dof_data, interp);
    out.add_data_vector(u, stress);
    // Largest boundary id of each cell's faces (0 for interior cells).
    dealii::Vector<float> bid(tria_.n_active_cells());
    for (const auto &cell : tria_.active_cell_iterators())
      for (const auto f : cell->face_indices())
        if (cell->at_boundary(f))
          bid[cell->active_cell_index()] =
            std::max<float>(bid[cell->active_cell_index()], cell->face(f)->boundary_id());
    out.add_data_vector(bid, "boundary_id", dealii::DataOut<2>::type_cell_data);
    out.build_patches(deformed, options_.degree, dealii::DataOut<2>::curved_inner_cells);
    AtomicOutputFile f(file);
    out.write_vtu(f.stream());
    f.commit();
  }

  void write_pvd(const std::filesystem::path &file,
                 const std::vector<std::pair<double, std::string>> &records)
  {
    AtomicOutputFile f(file);
    dealii::DataOutBase::write_pvd_record(f.stream(), records);
    f.commit();
  }
} // namespace gearfem::fem
