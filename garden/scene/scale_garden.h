// A generated garden for scale benches and tests (issue 25; docs/benchmarks.md,
// "Scale"): `count` copies of a garden file's own sculptures (their files,
// a[] and materials, taken in turn) on a square grid `spacing` metres
// apart, without the morph or paths, the visitor at the grid's near edge
// looking along its middle aisle. Nothing is written to disk.
#pragma once

#include <string>

#include "garden/scene/garden_file.h"

namespace hg::garden {

struct ScaleGardenSpec {
    int count = 48;
    double spacing = 3.0;  // metres between neighbouring sculptures
    int resolution = 0;    // voxels along the longest side; 0: each template sculpture's
};

// Rows and columns of the grid: columns = ceil(sqrt(count)).
int scaleGardenColumns(int count);

// The garden document (JSON text) made from the template garden's text.
// Throws JsonError when the template has no sculptures.
std::string scaleGardenText(const std::string& templateText, const ScaleGardenSpec& spec);

// Reads the template garden file, makes the scaled garden (its sculpture
// files resolved against the template's folder) and loads every sculpture's
// HyperFun body, as loadGarden does.
GardenLoad loadScaleGarden(const std::string& templatePath, const ScaleGardenSpec& spec);

}  // namespace hg::garden
