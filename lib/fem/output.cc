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

#include <cmath>
#include <memory>

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

  namespace
  {
    /// VTU output flags: zlib at its fastest level. At deal.II's default (best compression) the
    /// three 8 MB VTU files of the demo took 6 s to write, twice its 40-position contact sweep;
    /// the files read the same.
    dealii::DataOutBase::VtkFlags vtu_flags()
    {
      dealii::DataOutBase::VtkFlags flags;
      flags.compression_level = dealii::DataOutBase::VtkFlags::best_speed;
      return flags;
    }
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
    out.set_flags(vtu_flags());
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

  namespace
  {
    /// DataOut whose patches can be moved rigidly after build_patches().
    class PlacedDataOut : public dealii::DataOut<2>
    {
    public:
      void place(double angle, double cx, double cy)
      {
        const double c = std::cos(angle), s = std::sin(angle);
        const auto names = get_dataset_names();
        auto rows = [&](const std::string &n) {
          std::vector<unsigned int> r;
          for (unsigned int i = 0; i < names.size(); ++i)
            if (names[i] == n)
              r.push_back(i);
          return r;
        };
        const auto disp = rows("displacement"), trac = rows("contact_traction");
        const unsigned int sxx = rows("sigma_xx").at(0), syy = rows("sigma_yy").at(0),
                           sxy = rows("sigma_xy").at(0);
        for (auto &patch : patches)
          {
            for (auto &v : patch.vertices)
              v = dealii::Point<2>(cx + c * v[0] - s * v[1], cy + s * v[0] + c * v[1]);
            const unsigned int np = patch.data.n_cols();
            const unsigned int nr = patch.data.n_rows();
            for (unsigned int k = 0; k < np; ++k)
              {
                auto rot = [&](unsigned int a, unsigned int b) {
                  const double x = patch.data(a, k), y = patch.data(b, k);
                  patch.data(a, k) = c * x - s * y;
                  patch.data(b, k) = s * x + c * y;
                };
                if (patch.points_are_available)
                  {
                    const double x = patch.data(nr - 2, k), y = patch.data(nr - 1, k);
                    patch.data(nr - 2, k) = cx + c * x - s * y;
                    patch.data(nr - 1, k) = cy + s * x + c * y;
                  }
                rot(disp[0], disp[1]);
                rot(trac[0], trac[1]);
                const double a = patch.data(sxx, k), b = patch.data(syy, k), d = patch.data(sxy, k);
                patch.data(sxx, k) = c * c * a - 2 * s * c * d + s * s * b;
                patch.data(syy, k) = s * s * a + 2 * s * c * d + c * c * b;
                patch.data(sxy, k) = s * c * (a - b) + (c * c - s * s) * d;
              }
          }
      }
    };
  } // namespace

  void write_placed_vtu(const std::vector<PlacedBody> &bodies, const std::filesystem::path &file,
                        double scale)
  {
    if (bodies.empty())
      return;
    std::vector<std::unique_ptr<PlacedDataOut>> outs;
    std::vector<std::unique_ptr<StressPostprocessor>> pps;
    std::vector<std::unique_ptr<dealii::MappingQEulerian<2, dealii::Vector<double>>>> maps;
    std::vector<dealii::Vector<double>> keep;
    keep.reserve(4 * bodies.size());
    for (const auto &pb : bodies)
      {
        const ElasticBody &b = *pb.body;
        keep.emplace_back(*pb.u);
        keep.back() *= scale;
        maps.push_back(std::make_unique<dealii::MappingQEulerian<2, dealii::Vector<double>>>(
          b.options().degree, b.dof_handler(), keep.back()));
        pps.push_back(std::make_unique<StressPostprocessor>(b.material()));
        outs.push_back(std::make_unique<PlacedDataOut>());
        auto &out = *outs.back();
        out.attach_dof_handler(b.dof_handler());
        const std::vector<dealii::DataComponentInterpretation::DataComponentInterpretation> interp(
          2, dealii::DataComponentInterpretation::component_is_part_of_vector);
        keep.emplace_back(*pb.u);
        keep.back() *= 1e3;
        out.add_data_vector(keep.back(), std::vector<std::string>(2, "displacement"),
                            dealii::DataOut<2>::type_dof_data, interp);
        keep.emplace_back(b.n_dofs());
        if (pb.traction)
          {
            keep.back() = *pb.traction;
            keep.back() *= 1e-6;
          }
        out.add_data_vector(keep.back(), std::vector<std::string>(2, "contact_traction"),
                            dealii::DataOut<2>::type_dof_data, interp);
        out.add_data_vector(*pb.u, *pps.back());
        keep.emplace_back(b.triangulation().n_active_cells());
        auto &bid = keep.back();
        for (const auto &cell : b.triangulation().active_cell_iterators())
          for (const auto f : cell->face_indices())
            if (cell->at_boundary(f))
              bid[cell->active_cell_index()] =
                std::max<double>(bid[cell->active_cell_index()], cell->face(f)->boundary_id());
        out.add_data_vector(bid, "boundary_id", dealii::DataOut<2>::type_cell_data);
        out.build_patches(*maps.back(), b.options().degree, dealii::DataOut<2>::curved_inner_cells);
        out.place(pb.angle, pb.centre[0], pb.centre[1]);
      }
    for (std::size_t i = 1; i < outs.size(); ++i)
      outs[0]->merge_patches(*outs[i]);
    outs[0]->set_flags(vtu_flags());
    AtomicOutputFile f(file);
    outs[0]->write_vtu(f.stream());
    f.commit();
  }
} // namespace gearfem::fem
