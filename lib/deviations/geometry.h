#pragma once
// Single pitch deviations built into the geometry (`Deviations/Model = geometry`): each gear's
// teeth are turned about its centre by their cumulative pitch deviations in the mesh
// (mesh::GearMeshParameters::tooth_angles), and the full FE sweeps the positions of `Solve`.
// The independent check of the condensed route, which applies the same deviations as drive
// advances of the contact candidates (docs/deviations.md).
#include "geometry/pair.h"
#include "deviations/parameters.h"

#include <array>
#include <vector>

namespace gearfem::deviations
{
  /// Refuses what the geometry route cannot build into the mesh (InputError naming the entry,
  /// its value and what is allowed): an accuracy grade, profile slope and form deviations,
  /// flank offsets, runout, and a number of Deviations/Pitches (the positions are those of
  /// `Solve`).
  void check_geometry_model(const DeviationParameters &p);

  /// The tooth placement offsets delta_k [rad] of gears 1 and 2: the cumulative pitch
  /// deviation F_p,k about the teeth's mean over the reference radius r_ref = m z / 2,
  /// counter-clockwise for plus material on the loaded flank (PairDeviations::tooth_rotation,
  /// the rotation the condensed route applies). Empty for a gear without pitch deviations.
  /// `meshed` is the pair whose outlines are meshed (the unmodified pair on the gap route):
  /// InputError naming Deviations/Model when an outline has no root land arc, where turned
  /// teeth meet, and naming the single pitch deviations when one exceeds half a root land.
  std::array<std::vector<double>, 2> tooth_angles(const DeviationParameters &p, const geometry::GearPair &pair,
                                                  const geometry::GearPair &meshed);
} // namespace gearfem::deviations
