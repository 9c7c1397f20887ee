#pragma once
/// \file
/// Undoes edge bisections where the cloth no longer needs them.

#include "topology/cloth_complex.hpp"
#include "topology/refinement_options.hpp"
#include "topology/sizing_field.hpp"
#include "topology/spring_settings.hpp"

namespace tissu {

struct CoarseningReport {
  int merges = 0;  ///< bisections undone (particles removed)
};

/// One coarsening pass, by decreasing Particle::level: every particle created by refinement
/// (source_index -1; a midpoint pinned because its edge was clamped too) and not on a crack, whose
/// neighbourhood is still that of one bisection (the two halves of its parent edge plus one or
/// two cut edges), and whose parent edge is shorter than `hysteresis` in the sizing metric of
/// every face around it (compute_sizing with `options` and `inputs`, sizing_field.hpp) for
/// options.coarsen_after_passes passes in a row (Particle::calm_passes), is removed: its cut edges
/// are deleted (remove_cell<1>), then the vertex (remove_cell<0>), restoring the parent triangles.
/// Particles of the input mesh are never removed. Rest areas, masses and springs are recomputed
/// around each change; the removed particle's momentum is handed to the free corners so that the
/// linear momentum of the free particles is unchanged (the centre of mass moves by at most the
/// particle's mass times its distance to the parent edge's midpoint, which is zero while the cloth
/// is unbent).
CoarseningReport coarsen(ClothComplex& lcc, const RefinementOptions& options, double hysteresis,
                         const SpringSettings& settings, const SizingInputs& inputs = {});

/// coarsen() on the sizing field the faces hold (FaceRest::sizing_per_m2), without computing it
/// again: for a pass right after refine(), which computed it. The faces refine() split hold their
/// parent's value (CGAL copies a face's attribute into both faces it is split into), which keeps
/// every particle it made (its parent face wanted the split edge shorter than the target, far
/// from under `hysteresis` of it). On the curtain demo this saves about a third of the time spent
/// adapting, for the same shape (docs/benchmarks.md, "the sizing field once a pass").
CoarseningReport coarsen_on_current_sizing(ClothComplex& lcc, const RefinementOptions& options,
                                           double hysteresis, const SpringSettings& settings);

}  // namespace tissu
