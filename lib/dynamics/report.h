#pragma once
// The analyses of a dynamics case as one library call: the time response, the phase
// portraits at chosen speeds and the up/down speed sweep of `DynamicsCase`, turned into the
// output tables (response, poincare, spectrum, portrait_<k>_*, sweep; docs/output-format.md)
// and the summary text. `gearfem dynamics` writes them; a batch driver can call the same.
#include "base/table.h"
#include "base/units.h"
#include "dynamics/analysis.h"
#include "dynamics/case.h"

#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace gearfem::dynamics
{
  /// Output scaling: SI -> engineering units, or the dimensionless Kahraman-Singh x.
  struct OutputUnits
  {
    bool ks = false;
    double d_scale = 1e6, d_offset = 0; ///< DTE [um] (KS: x = delta + 1 [-])
    std::string d_unit = "um", v_unit = "mm/s", f_unit = "N", t_unit = "s", hz = "Hz", speed_unit = "rpm";
    double v_scale = 1e3, speed_scale = 60 / (2 * units::pi);
    explicit OutputUnits(bool kahraman_singh);
  };

  /// Response, Poincare and spectrum tables of a time response (named "response",
  /// "poincare", "spectrum").
  std::vector<std::pair<std::string, Table>> response_tables(const Response &r, const MeshModel &m,
                                                             const OutputUnits &u);
  /// One row per sweep point.
  Table sweep_table(const std::vector<SweepPoint> &points, const OutputUnits &u);

  struct CaseReport
  {
    /// (name, table): each is written as <name>.csv and as group <name> of response.h5.
    std::vector<std::pair<std::string, Table>> tables;
    std::string summary; ///< summary.txt
    long clamps = 0;     ///< mesh-force table evaluations outside the table range
  };

  /// Run the analyses the case asks for on `model` (cloned for each response), printing
  /// progress and the main figures to `out` (may be null).
  CaseReport run_case(const DynamicsCase &c, const MeshModel &model, std::ostream *out);
} // namespace gearfem::dynamics
