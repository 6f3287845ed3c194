#include "gearbox/study.h"

#include "base/errors.h"
#include "base/number.h"
#include "io/solve_results.h"

namespace gearfem::gearbox
{
  const char *source_name(StressSource s)
  {
    return s == StressSource::table ? "table" :
           s == StressSource::fe    ? "FE" :
           s == StressSource::iso   ? "ISO" :
                                      "AGMA";
  }

  std::string apply_standard_source(GearboxResult &r, const GearboxStudy &study)
  {
    const GearboxInput &in = study.input;
    if (study.source == StressSource::table)
      {
        use_reference_stresses(r, in, study.reference, study.reference_torque);
        return "table (given at " + to_string_g(study.reference_torque) +
               " N m, sigma_H scaled with sqrt(M), sigma_F with M)";
      }
    if (study.source == StressSource::iso)
      {
        use_stress_table(r, in, iso_stresses(r.stress));
        return "ISO 6336-2 (sigma_H = max(sigma_H1, sigma_H2) of the mesh; K_A, K_v, K_Hbeta of the Rating "
               "section, K_Halpha = 1) and ISO 6336-3 method B (sigma_F) from the geometry";
      }
    return "AGMA 2101-D04 / 908-B89 from the geometry";
  }

  void write_gearbox_outputs(const GearboxInput &in, const GearboxResult &r, const std::string &source,
                             const std::filesystem::path &dir, const std::string &input_name,
                             const std::string &fe_text)
  {
    write_markdown(in, r, source, dir / "gearbox.md", "Gearbox rating (" + input_name + ")", fe_text);
    write_csv(in, r, dir);
    write_sn_csv(in, r, dir / "gearbox_sn.csv");
    const GearboxTables t = gearbox_tables(in, r);
    io::write_table_file({{"meshes", &t.meshes}, {"lives", &t.lives}}, dir / "gearbox.h5",
                         {{"format", "gearfem-gearbox"}, {"format_version", "1"}, {"input", input_name},
                          {"stress source", source}},
                         {{"meshes", "stage [text]", t.mesh_stage}, {"meshes", "mesh [text]", t.mesh_name},
                          {"lives", "stage [text]", t.life_stage}, {"lives", "member [text]", t.life_member},
                          {"lives", "mode [text]", t.life_mode}, {"lives", "load [text]", t.life_load}});
  }
} // namespace gearfem::gearbox
