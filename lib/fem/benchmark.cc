// The fem benchmark: three mesh levels of a full gear under tip load.
#include "fem/benchmark.h"

#include "base/errors.h"
#include "base/memory.h"
#include "fem/parameters.h"
#include "fem/tooth_load.h"
#include "geometry/parameters.h"
#include "mesh/parameters.h"

#include <deal.II/base/parameter_handler.h>


#include <cmath>
#include <iomanip>

namespace gearfem::fem
{
  void benchmark(const std::filesystem::path &prm_file, std::ostream &out)
  {
    dealii::ParameterHandler prm;
    geometry::declare_geometry_parameters(prm);
    geometry::declare_material_parameters(prm);
    mesh::declare_mesh_parameters(prm);
    declare_fe_parameters(prm);
    if (!std::filesystem::is_regular_file(prm_file))
      throw InputError("input file", prm_file.string(), "an existing readable file");
    prm.parse_input(prm_file.string(), "", true, false); // ignore other commands' sections
    const auto gi = geometry::parse_geometry_parameters(prm);
    const auto pm = geometry::parse_material_parameters(prm);
    FeOptions fe  = parse_fe_parameters(prm);
    fe.degree     = 2;
    auto mp       = mesh::parse_mesh_parameters(prm, 1);
    mp.model      = mesh::GearMeshParameters::Model::full_gear;
    const auto tooth = geometry::ToothProfile::generate(gi.gear1);
    const auto &g    = tooth.parameters();
    const Elasticity material = elasticity(pm.gear1, g.face_width, pm.plane_strain);

    FlankLoad load;
    const double Ft   = 100e6 * g.face_width * g.rack.module; // F_t/(b m) = 100 MPa
    load.normal_force = Ft / std::cos(g.rack.pressure_angle);

    out << "fem benchmark: gear 1 of " << prm_file.filename().string() << " (z " << g.teeth << ", m "
        << g.rack.module * 1e3 << " mm, b " << g.face_width * 1e3
        << " mm), full gear, Q2, clamped bore, tip load F_t/(b m) = 100 MPa on tooth 0, fine teeth "
        << mp.fine_teeth << "\n\n"
        << "| h_contact = h_fillet [mm] | cells | DoFs | mesh [s] | assemble [s] | factorise [s] | "
           "solve [s] | solver | peak memory [MB] | fillet sigma_1 [MPa] | error vs finest [%] |\n"
        << "|---|---|---|---|---|---|---|---|---|---|---|\n";
    const double h[3] = {0.4e-3, 0.2e-3, 0.1e-3};
    std::vector<FlankLoadResult> res;
    std::vector<double> memory;
    for (double hc : h)
      {
        mp.h_contact = mp.h_fillet = hc;
        res.push_back(solve_flank_load(tooth, mp, material, fe, load));
        res.back().t_assemble += res.back().t_setup; // setup (mapping cache, DoFs) counts as assembly
        memory.push_back(peak_memory_mb());
      }
    for (std::size_t i = 0; i < res.size(); ++i)
      {
        const auto &r = res[i];
        const double err = (r.fillet_peak.value - res.back().fillet_peak.value) / res.back().fillet_peak.value;
        out << std::fixed << "| " << std::setprecision(2) << h[i] * 1e3 << " | " << r.n_cells << " | "
            << r.n_dofs << " | " << r.t_mesh << " | " << r.t_assemble << " | " << r.t_factorize
            << " | " << std::setprecision(3) << r.t_solve << " | " << to_string(r.solver) << " | "
            << std::setprecision(0) << memory[i] << " | " << std::setprecision(1)
            << r.fillet_peak.value / 1e6 << " | " << std::setprecision(2) << 100 * err << " |\n";
      }
    out << std::defaultfloat << "\nTargets (2-core machine): mesh <= 5 s and assemble + solve (Q2) "
        << "<= 10 s for h_contact = 0.1 mm on 5 teeth. Finest level: mesh " << res.back().t_mesh
        << " s, assemble + factorise + solve "
        << res.back().t_assemble + res.back().t_factorize + res.back().t_solve << " s.\n";
  }
} // namespace gearfem::fem
