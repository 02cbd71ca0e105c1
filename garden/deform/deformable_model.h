// The deformable model (issue 22; the seed's snakes, docs/sketching.md
// "Deformable model"): a closed mesh that shrinks onto a sculpture's
// surface from outside (shrink-wrap) or grows onto it from inside
// (blow-up), a step per iteration. Where the sculpture's narrow-band grid
// gives no gradient a vertex moves along its inverted normal (Shrink) or
// its normal (Grow); where it does, toward the surface f = 0 along the
// gradient, stopping where f changes sign, the gradient turns or its
// magnitude falls. The seed's neighbourhood restriction pulls back a vertex
// that ran off from its neighbours, tangential smoothing and periodic
// split / collapse / flip keep the triangulation uniform.
//
// Deterministic: every vertex's step reads the previous iteration's
// positions only, and the remeshing runs on the iteration count, so N calls
// of deform(1) give bit for bit what one deform(N) gives (the live tool
// runs a budgeted number a frame; the journal replays them in one go).
#pragma once

#include "garden/deform/deform_mesh.h"
// The rest of the deformable model's API, so that one include brings it:
// uniform remeshing, the sketch's mesh, the selection.
#include "garden/deform/remesh.h"
#include "garden/deform/selection.h"
#include "garden/deform/sketch_mesh.h"

namespace hg::voxel {
class Volume;
}

namespace hg::garden::deform {

enum class DeformMode { Shrink, Grow };

struct DeformOptions {
    // The step along the normal where the grid has no gradient, and the
    // longest step along it, in voxels of the sculpture's grid.
    double stepVoxels = 0.75;
    // Remesh (one round of split, collapse, flip) every this many
    // iterations, counted from the model's first.
    int remeshEvery = 4;
    // Tangential smoothing toward the neighbours' centroid, per iteration.
    double tangentialSmoothing = 0.3;
    // The seed's restriction: a vertex farther than this many mean edge
    // lengths from its neighbours' centroid is put back on the centroid.
    double runOffEdges = 2.0;
    // Settled: no vertex moved more than this many voxels in an iteration.
    double settledVoxels = 0.05;
    // Over the vertices on TBB workers (the result is the same either way).
    bool parallel = true;
};

class DeformableModel {
public:
    DeformableModel(DeformMesh mesh, double edgeLength, DeformOptions options = {});

    // `iterations` steps against `volume` (the sculpture's grid, in its
    // model frame, the model's frame too). Nothing moves on a volume with
    // no frame (voxel size 0: an empty Volume()).
    void deform(const voxel::Volume& volume, DeformMode mode, int iterations);

    const DeformMesh& mesh() const { return mesh_; }
    double edgeLength() const { return edgeLength_; }
    int iterationsRun() const { return iterations_; }
    // No vertex moved more than options.settledVoxels in the last iteration.
    bool settled() const { return settled_; }
    // The largest vertex move of the last iteration (model units).
    double lastMove() const { return lastMove_; }

    void setParallel(bool parallel) { options_.parallel = parallel; }

private:
    void step(const voxel::Volume& volume, DeformMode mode);
    void rebuildTopology();

    DeformMesh mesh_;
    double edgeLength_;
    DeformOptions options_;
    int iterations_ = 0;
    bool settled_ = false;
    double lastMove_ = 0.0;
    // The one-rings and fans of mesh_, rebuilt when the remesher changes it.
    std::vector<MeshEdge> edges_;
    VertexLists ring_, fan_;
};

}  // namespace hg::garden::deform
