#include "gearbox/fe/source.h"

namespace gearfem::gearbox::fe
{
  FeSourceOutcome apply_fe_source(gb::GearboxResult &r, const gb::GearboxInput &in, const FeStressOptions &options,
                                  const std::filesystem::path &table_file)
  {
    const FeStressResult f = fe_stress_table(in, r.train, r.stress, options);
    gb::use_stress_table(r, in, f.stress);
    write_fe_stresses(f, table_file);
    FeSourceOutcome o;
    o.text    = fe_markdown(f, options);
    o.failure = f.failure;
    o.source  = "FE (external meshes: gearfem solve sector models, Hertz from the FE load share and "
                "fillet sigma_1, maxima over the mesh cycle; internal meshes: AGMA 2101-D04 / 908-B89)";
    return o;
  }
} // namespace gearfem::gearbox::fe
