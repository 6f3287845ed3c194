// The geometry report of `gearfem profile`.
#include "geometry/profile_report.h"

#include "base/atomic_file.h"
#include "base/units.h"

#include <cmath>
#include <iomanip>

namespace gearfem::geometry
{
  namespace
  {
    /// Numeric codes of the CSV columns (documented in the header line and docs/geometry.md).
    int code(SegmentType t) { return static_cast<int>(t); }
    int code(Side s) { return s == Side::coast ? 0 : s == Side::drive ? 1 : -1; }

    void write_quantities(const std::vector<PairQuantity> &rows, const std::filesystem::path &file)
    {
      AtomicOutputFile f(file);
      f << "quantity,value,unit\n";
      f.stream() << std::setprecision(12);
      for (const auto &r : rows)
        f << r.name << "," << r.value << "," << r.unit << "\n";
      f.commit();
    }
  } // namespace

  Table profile_table(const ToothProfile &g)
  {
    Table t;
    t.add_column("x", "mm");
    t.add_column("y", "mm");
    t.add_column("nx", "-");
    t.add_column("ny", "-");
    t.add_column("curvature", "1/mm");
    t.add_column("type (0 root; 1 fillet; 2 flank; 3 tip rounding; 4 tip)", "-");
    t.add_column("side (0 coast; 1 drive; -1 tip)", "-");
    t.add_column("tooth", "-");
    t.add_column("segment", "-");
    t.add_column("s", "-");
    const double spacing = g.parameters().rack.module / 40;
    for (const auto &q : g.sample_gear(spacing))
      t.add_row({q.p.x() / units::mm, q.p.y() / units::mm, q.normal.x(), q.normal.y(),
                 q.curvature * units::mm, double(code(q.type)), double(code(q.side)),
                 double(q.tooth), double(q.segment), q.s});
    return t;
  }

  std::vector<PairQuantity> pair_quantities(const GearPair &pair)
  {
    const double mm = units::mm, deg = units::deg;
    const auto  &p1 = pair.gear(1).parameters();
    const double m  = p1.rack.module;
    std::vector<PairQuantity> r = {
      {"module", m / mm, "mm"},
      {"pressure angle", p1.rack.pressure_angle / deg, "deg"},
      {"z1", double(pair.gear(1).teeth()), "-"},
      {"z2", double(pair.gear(2).teeth()), "-"},
      {"centre distance", pair.center_distance() / mm, "mm"},
      {"zero-backlash centre distance", pair.zero_backlash_center_distance() / mm, "mm"},
      {"working pressure angle", pair.working_pressure_angle() / deg, "deg"},
      {"transverse contact ratio", pair.contact_ratio(), "-"},
      {"base pitch", pair.base_pitch() / mm, "mm"},
      {"normal backlash", pair.normal_backlash() / units::um, "um"},
      {"circumferential backlash", pair.circumferential_backlash() / units::um, "um"},
      {"equivalent curvature at C", pair.equivalent_curvature(0.0) * mm, "1/mm"},
    };
    for (int i : {1, 2})
      {
        const auto       &g = pair.gear(i);
        const std::string s = " " + std::to_string(i);
        const auto       &k = g.radii();
        r.push_back({"profile shift x" + s, g.parameters().profile_shift, "-"});
        r.push_back({"reference radius" + s, k.reference / mm, "mm"});
        r.push_back({"base radius" + s, k.base / mm, "mm"});
        r.push_back({"working pitch radius" + s, pair.working_pitch_radius(i) / mm, "mm"});
        r.push_back({"tip radius" + s, k.tip / mm, "mm"});
        r.push_back({"root radius" + s, k.root / mm, "mm"});
        r.push_back({"form radius" + s, k.form / mm, "mm"});
        r.push_back({"start of active profile radius" + s,
                     (i == 1 ? pair.point("A").r1 : pair.point("E").r2) / mm, "mm"});
        r.push_back({"tip relief start radius" + s, k.relief_start / mm, "mm"});
        r.push_back({"tip thickness" + s, g.tip_thickness() / mm, "mm"});
        r.push_back({"tip clearance" + s, pair.tip_clearance(i) / mm, "mm"});
        r.push_back({"undercut depth" + s, g.undercut().depth / units::um, "um"});
        r.push_back({"undercut radius" + s, g.undercut().radius / mm, "mm"});
        r.push_back({"Z_min without undercut" + s,
                     minimum_teeth_without_undercut(g.parameters().rack.pressure_angle,
                                                    g.parameters().rack.dedendum,
                                                    g.parameters().rack.root_radius,
                                                    g.parameters().profile_shift),
                     "-"});
      }
    for (const auto &q : pair.line_of_action())
      {
        r.push_back({q.name + " g (from T1)", q.g / mm, "mm"});
        r.push_back({q.name + " g per module (AGMA 908 C-value)", q.g / m, "-"});
        r.push_back({q.name + " roll angle", q.roll_angle / deg, "deg"});
        r.push_back({q.name + " x", q.position.x() / mm, "mm"});
        r.push_back({q.name + " y", q.position.y() / mm, "mm"});
        r.push_back({q.name + " r1", q.r1 / mm, "mm"});
        r.push_back({q.name + " r2", q.r2 / mm, "mm"});
      }
    // Placements at the pitch point (phi1 = 0), for the plot.
    for (int i : {1, 2})
      {
        const auto pl = pair.placement(i, 0.0);
        r.push_back({"gear " + std::to_string(i) + " centre x", pl.centre.x() / mm, "mm"});
        r.push_back({"gear " + std::to_string(i) + " centre y", pl.centre.y() / mm, "mm"});
        r.push_back({"gear " + std::to_string(i) + " angle at C", pl.angle / deg, "deg"});
      }
    return r;
  }

  Table contact_path_table(const GearPair &pair)
  {
    Table t;
    t.add_column("roll angle", "deg");
    t.add_column("g", "mm");
    t.add_column("x", "mm");
    t.add_column("y", "mm");
    t.add_column("equivalent curvature", "1/mm");
    const double a = pair.point("A").roll_angle, e = pair.point("E").roll_angle;
    const int    n = 200;
    for (int k = 0; k <= n; ++k)
      {
        const double phi = a + (e - a) * k / n;
        const Vec2   P   = pair.path_point(phi);
        t.add_row({phi / units::deg, (pair.point("C").g + pair.base_radius(1) * phi) / units::mm,
                   P.x() / units::mm, P.y() / units::mm, pair.path_curvature(phi) * units::mm});
      }
    return t;
  }

  void print_pair_summary(const GearPair &pair, const PairMaterial &mat, std::ostream &out)
  {
    const double mm = units::mm;
    out << std::fixed << std::setprecision(4);
    out << "pair " << pair.gear(1).teeth() << "/" << pair.gear(2).teeth() << ", m "
        << pair.gear(1).parameters().rack.module / mm << " mm, a " << pair.center_distance() / mm
        << " mm, alpha_w " << pair.working_pressure_angle() / units::deg << " deg\n";
    for (int i : {1, 2})
      {
        const auto &k = pair.gear(i).radii();
        out << "gear " << i << ": r " << k.reference / mm << ", rb " << k.base / mm << ", ra "
            << k.tip / mm << ", rf " << k.root / mm << ", r_Ff " << k.form / mm << " mm, s_a "
            << pair.gear(i).tip_thickness() / mm << " mm, E "
            << (i == 1 ? mat.gear1 : mat.gear2).youngs_modulus / units::GPa << " GPa\n";
      }
    out << "line of action (g from T1, mm; roll angle, deg):";
    for (const auto &q : pair.line_of_action())
      out << " " << q.name << " " << q.g / mm << " (" << q.roll_angle / units::deg << ")";
    out << "\ncontact ratio " << pair.contact_ratio() << ", backlash jn "
        << pair.normal_backlash() / units::um << " um, jt "
        << pair.circumferential_backlash() / units::um << " um, 1/R(C) "
        << pair.equivalent_curvature(0.0) * mm << " 1/mm\n";
    out.unsetf(std::ios::floatfield);
    for (int i : {1, 2})
      for (const auto &w : pair.gear(i).warnings())
        out << w << "\n";
    for (const auto &w : pair.warnings())
      out << w << "\n";
  }

  void write_profile_report(const GearPair &pair, const std::filesystem::path &dir)
  {
    profile_table(pair.gear(1)).write_csv(dir / "profile_gear1.csv", 12);
    profile_table(pair.gear(2)).write_csv(dir / "profile_gear2.csv", 12);
    write_quantities(pair_quantities(pair), dir / "pair.csv");
    contact_path_table(pair).write_csv(dir / "contact_path.csv", 10);
  }
} // namespace gearfem::geometry
