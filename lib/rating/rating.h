#pragma once
// Ratings of a generated pair (lib/geometry GearPair): ISO 6336-1/-2/-3 (method B) and
// AGMA 2101-D04 / 908-B89, as an auditable list of factors, each with its clause, value
// and unit. SI inputs; the report is in engineering units (MPa, mm, N, N/(mm um)).
#include "rating/agma.h"
#include "geometry/pair.h"

#include <filesystem>
#include <string>
#include <vector>

namespace gearfem::rating
{
  /// Load and rating-factor choices (defaults: Siasos 2010, sec. 4.1).
  struct RatingInput
  {
    std::vector<double> torques{500, 400, 300, 200}; ///< pinion torques [N m]
    double speed = 0.0;                              ///< pinion speed [rpm] (pitch-line velocity only)
    double E1 = 206e9, nu1 = 0.3, E2 = 206e9, nu2 = 0.3;
    // AGMA 2101-D04
    double K_o = 1.0, K_v = 1.05, K_s = 1.0, Z_R = 1.0;
    double K_B = 1.0;                  ///< rim thickness factor (1: m_B >= 1.2)
    agma::Enclosure enclosure = agma::Enclosure::precision;
    double K_H = 0.0;                  ///< load distribution factor; 0 = 1 + K_Hma + K_Hpf
    agma::Tool tool;                   ///< AGMA 908 generating tool (n_o = 10000 = hob)
    // ISO 6336
    double K_A = 1.0;                  ///< application factor
    double K_v_iso = 1.05;             ///< dynamic factor
    double K_Hbeta = 1.0;              ///< face load factor (contact); K_Fbeta from it (ISO 6336-1 eq. 41)
    int accuracy_grade = 0;            ///< ISO 1328-1 grade for K_Halpha (method B); 0: K_Halpha = K_Falpha = 1
    bool case_hardened = true;         ///< running-in allowance y_alpha = 0.075 f_pb (else 160/sigma_Hlim f_pb)
    double sigma_Hlim = 1500e6;        ///< [Pa] for y_alpha of through-hardened steel
  };

  /// One audited factor: the standard, what it is, its symbol, the clause, the unit and one
  /// value per torque (constant factors repeat).
  struct RatingRow
  {
    std::string standard, quantity, symbol, clause, unit;
    std::vector<double> values;
  };

  struct RatingReport
  {
    std::vector<double> torques; ///< [N m]
    std::vector<RatingRow> rows;
    /// Value of a row by symbol and standard (throws if absent).
    const RatingRow &row(const std::string &standard, const std::string &symbol) const;
    /// Markdown report (one table per standard) and CSV, written atomically.
    void write_markdown(const std::filesystem::path &file, const std::string &title) const;
    void write_csv(const std::filesystem::path &file) const;
    /// Append a row of `standard` (one value per torque); SolverError naming `what`, the
    /// standard and the symbol for a value that is not finite.
    void add(const std::string &what, const std::string &standard, const std::string &quantity,
             const std::string &symbol, const std::string &clause, const std::string &unit, std::vector<double> v);
  };

  /// The rows of one standard of a report, as its rating code adds them.
  struct RowBuilder
  {
    RatingReport &r;
    std::string standard;
    std::string what = "rating"; ///< names the rating in the error of a value that is not finite
    void add(const std::string &q, const std::string &sym, const std::string &clause, const std::string &unit,
             std::vector<double> v)
    {
      r.add(what, standard, q, sym, clause, unit, std::move(v));
    }
    void constant(const std::string &q, const std::string &sym, const std::string &clause, const std::string &unit,
                  double x)
    {
      add(q, sym, clause, unit, std::vector<double>(r.torques.size(), x));
    }
  };

  /// Rate the pair for each torque. Throws InputError for bad factors (K <= 0, ...).
  RatingReport rate(const geometry::GearPair &pair, const RatingInput &in);
} // namespace gearfem::rating
