#include "voxel/scalar_volume.h"

#include <openvdb/tools/LevelSetRebuild.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>
#include <vector>

#include "voxel/memory_guard.h"
#include "voxel/vdb_grids.h"
#include "voxel/volume_vdb.h"

namespace hg::voxel {

struct ScalarGrid {
    openvdb::FloatGrid::Ptr grid;  // the samples, in the file's transform
    bool padded = false;           // a raw volume: one background sample around the data (below)
};

ScalarVolume::ScalarVolume() = default;
ScalarVolume::~ScalarVolume() = default;
ScalarVolume::ScalarVolume(ScalarVolume&&) noexcept = default;
ScalarVolume& ScalarVolume::operator=(ScalarVolume&&) noexcept = default;

namespace {

using Clock = std::chrono::steady_clock;

std::string formatValue(double v) {
    std::ostringstream s;
    s << v;
    return s.str();
}

// Leaves of 8^3 voxels, four bytes a voxel, times what the rebuild holds
// beside our grid (its distance grid and the closest-triangle index grid).
constexpr double kBytesPerBandVoxel = 12.0;

}  // namespace

std::string readRawVolume(const std::string& path, const RawVolumeLayout& layout, ScalarVolume& out) {
    for (int a = 0; a < 3; ++a) {
        if (layout.dims[static_cast<std::size_t>(a)] < kMinRawDim || layout.dims[static_cast<std::size_t>(a)] > kMaxRawDim)
            return "dimensions must be in [" + std::to_string(kMinRawDim) + ", " + std::to_string(kMaxRawDim) + "]";
        const double s = layout.spacing[static_cast<std::size_t>(a)];
        if (!(s > 0.0) || !std::isfinite(s)) return "the spacing must be finite and positive";
    }
    const int nx = layout.dims[0], ny = layout.dims[1], nz = layout.dims[2];
    const std::uint64_t count = std::uint64_t(nx) * std::uint64_t(ny) * std::uint64_t(nz);
    const std::uint64_t bytesPerSample = layout.type == SampleType::U16 ? 2 : 1;
    std::ifstream in(path, std::ios::binary | std::ios::ate);
    if (!in) return path + ": cannot open: " + std::strerror(errno);
    const std::uint64_t size = static_cast<std::uint64_t>(in.tellg());
    const char* typeName = layout.type == SampleType::U16 ? "u16" : "u8";
    if (size != count * bytesPerSample)
        return path + ": " + std::to_string(size) + " bytes, but dims " + std::to_string(nx) + " x " +
               std::to_string(ny) + " x " + std::to_string(nz) + " of " + typeName + " need " +
               std::to_string(count * bytesPerSample) + " bytes";
    std::vector<unsigned char> bytes(static_cast<std::size_t>(size));
    in.seekg(0);
    if (!in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(size)))
        return path + ": cannot read: " + std::strerror(errno);

    ensureOpenVdbInitialized();
    std::vector<float> samples(static_cast<std::size_t>(count));
    float lo = std::numeric_limits<float>::max(), hi = std::numeric_limits<float>::lowest();
    for (std::size_t n = 0; n < samples.size(); ++n) {
        const float v = bytesPerSample == 2 ? static_cast<float>(bytes[2 * n] | (bytes[2 * n + 1] << 8))
                                            : static_cast<float>(bytes[n]);
        samples[n] = v;
        lo = std::min(lo, v);
        hi = std::max(hi, v);
    }
    // The samples as they are; levelSetFromScalar turns them into a field.
    // The background is the lowest sample: what "outside the data" reads
    // until a request picks its side.
    openvdb::FloatGrid::Ptr grid = openvdb::FloatGrid::create(lo);
    openvdb::FloatGrid::Accessor acc = grid->getAccessor();
    std::size_t n = 0;
    for (int k = 0; k < nz; ++k)
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i) acc.setValue(openvdb::Coord(i, j, k), samples[n++]);
    openvdb::Mat4d scale = openvdb::Mat4d::identity();
    for (int a = 0; a < 3; ++a) scale(a, a) = layout.spacing[static_cast<std::size_t>(a)];
    grid->setTransform(openvdb::math::Transform::createLinearTransform(scale));
    auto g = std::make_shared<ScalarGrid>();
    g->grid = grid;
    g->padded = true;
    out.grid = std::move(g);
    out.minValue = static_cast<double>(lo);
    out.maxValue = static_cast<double>(hi);
    std::ostringstream d;
    d << nx << " x " << ny << " x " << nz << " " << typeName << " samples, spacing " << layout.spacing[0] << " x "
      << layout.spacing[1] << " x " << layout.spacing[2] << ", values " << lo << " to " << hi;
    out.description = d.str();
    return "";
}

std::string readScalarVdb(const std::string& path, const std::string& gridName, ScalarVolume& out) {
    openvdb::GridPtrVecPtr grids;
    if (std::string why = readVdbGrids(path, grids); !why.empty()) return why;
    std::string names;
    openvdb::FloatGrid::Ptr found;
    for (const openvdb::GridBase::Ptr& base : *grids) {
        names += std::string(names.empty() ? "" : ", ") + "'" + base->getName() + "' (" + base->valueType() + ")";
        if (found || (!gridName.empty() && base->getName() != gridName)) continue;
        found = openvdb::gridPtrCast<openvdb::FloatGrid>(base);
        if (!found && !gridName.empty())
            return path + ": grid '" + gridName + "' holds " + base->valueType() + " values, not float";
    }
    if (names.empty()) names = "none";
    if (!found)
        return path + ": " + (gridName.empty() ? std::string("no float grid") : "no grid named '" + gridName + "'") +
               " (its grids: " + names + ")";
    float lo = found->background(), hi = found->background();
    for (auto it = found->cbeginValueAll(); it; ++it) {
        lo = std::min(lo, *it);
        hi = std::max(hi, *it);
    }
    auto g = std::make_shared<ScalarGrid>();
    g->grid = found;
    out.levelSet = found->getGridClass() == openvdb::GRID_LEVEL_SET;
    out.grid = std::move(g);
    out.minValue = static_cast<double>(lo);
    out.maxValue = static_cast<double>(hi);
    std::ostringstream d;
    d << "float grid '" << found->getName() << "', " << found->activeVoxelCount() << " active voxels, values " << lo
      << " to " << hi;
    out.description = d.str();
    return "";
}

namespace {

// The samples as a field that is negative inside (OpenVDB's level-set
// side), iso at 0, and what the scan of it found: the index box of the
// inside samples and how many of them touch the outside (the surface's
// size, for the memory guard).
struct InsideField {
    openvdb::FloatGrid::Ptr field;
    openvdb::CoordBBox inside;
    std::uint64_t surfaceSamples = 0;
};

std::string insideField(const ScalarVolume& volume, const IsoSurfaceRequest& request, InsideField& out) {
    const ScalarGrid& samples = *volume.grid;
    const openvdb::FloatGrid& in = *samples.grid;
    const float iso = static_cast<float>(request.iso);
    const float sign = request.insideAbove ? -1.0f : 1.0f;  // field = sign * (sample - iso)
    // Outside the samples is outside: for a raw volume always (any positive
    // value will do; the data's span keeps it on the samples' scale), for a
    // .vdb where its background says so.
    const float background = samples.padded ? static_cast<float>(std::max(1.0, volume.maxValue - volume.minValue))
                                            : sign * (in.background() - iso);
    if (!(background > 0.0f))
        return "the value outside the volume's voxels (" + formatValue(in.background()) + ") is " +
               (request.insideAbove ? "above" : "below") +
               " the iso-value, so the solid would have no end; pick another iso-value or 'inside'";
    openvdb::FloatGrid::Ptr field = in.deepCopy();
    // A raw volume's samples are all active: what is not is outside.
    for (auto it = field->beginValueAll(); it; ++it)
        it.setValue(samples.padded && !it.isValueOn() ? background : sign * (*it - iso));
    field->tree().root().setBackground(background, false);
    if (samples.padded) {
        // A raw volume ends where its samples end: one layer of outside
        // samples around them closes a solid cut by the data's faces there.
        const openvdb::CoordBBox data = in.evalActiveVoxelBoundingBox();
        openvdb::FloatGrid::Accessor acc = field->getAccessor();
        const openvdb::Coord lo = data.min().offsetBy(-1), hi = data.max().offsetBy(1);
        for (int k = lo.z(); k <= hi.z(); ++k)
            for (int j = lo.y(); j <= hi.y(); ++j)
                for (int i = lo.x(); i <= hi.x(); ++i)
                    if (i == lo.x() || i == hi.x() || j == lo.y() || j == hi.y() || k == lo.z() || k == hi.z())
                        acc.setValue(openvdb::Coord(i, j, k), background);
    }
    openvdb::FloatGrid::ConstAccessor acc = field->getConstAccessor();
    static const openvdb::Coord kSides[6] = {openvdb::Coord(1, 0, 0),  openvdb::Coord(-1, 0, 0),
                                             openvdb::Coord(0, 1, 0),  openvdb::Coord(0, -1, 0),
                                             openvdb::Coord(0, 0, 1),  openvdb::Coord(0, 0, -1)};
    for (auto it = field->cbeginValueAll(); it; ++it) {
        if (!(*it < 0.0f)) continue;
        if (it.isTileValue()) {
            openvdb::CoordBBox b;
            it.getBoundingBox(b);
            out.inside.expand(b);
            continue;
        }
        const openvdb::Coord c = it.getCoord();
        out.inside.expand(c);
        for (const openvdb::Coord& d : kSides)
            if (!(acc.getValue(c + d) < 0.0f)) {
                ++out.surfaceSamples;
                break;
            }
    }
    if (out.inside.empty()) return "no sample is inside the iso-surface";
    out.field = field;
    return "";
}

// The inside samples' index box grown by one sample (the surface lies
// within one sample of them), in model units.
frep::Box3 modelBoxOf(const openvdb::FloatGrid& field, const openvdb::CoordBBox& inside) {
    const openvdb::Vec3d lo = inside.min().asVec3d() - openvdb::Vec3d(1.0);
    const openvdb::Vec3d hi = inside.max().asVec3d() + openvdb::Vec3d(1.0);
    frep::Box3 box;
    for (int a = 0; a < 3; ++a) {
        box.lo[a] = std::numeric_limits<double>::max();
        box.hi[a] = std::numeric_limits<double>::lowest();
    }
    for (int corner = 0; corner < 8; ++corner) {
        const openvdb::Vec3d p((corner & 1) ? hi.x() : lo.x(), (corner & 2) ? hi.y() : lo.y(),
                               (corner & 4) ? hi.z() : lo.z());
        const openvdb::Vec3d w = field.transform().indexToWorld(p);
        for (int a = 0; a < 3; ++a) {
            box.lo[a] = std::min(box.lo[a], w[a]);
            box.hi[a] = std::max(box.hi[a], w[a]);
        }
    }
    return box;
}

}  // namespace

// Distance in model units (negative inside) to ours: voxels, positive
// inside, clamped to the band; the invariants of volume.h (active exactly
// inside the band, ±band elsewhere, nothing outside the index box).
openvdb::FloatGrid::Ptr levelSetToOurGrid(const openvdb::FloatGrid& distance, const VolumeFrame& frame) {
    const double band = frame.band;
    const auto ours = [&](float d) {
        return static_cast<float>(std::clamp(-static_cast<double>(d) / frame.voxelSize, -band, band));
    };
    openvdb::FloatGrid::Ptr out = openvdb::FloatGrid::create(-frame.band);
    out->setTransform(frameTransform(frame));
    openvdb::FloatTree& tree = out->tree();
    openvdb::FloatGrid::Accessor acc = out->getAccessor();
    for (auto it = distance.cbeginValueAll(); it; ++it) {
        const float v = ours(*it);
        if (v == -frame.band) continue;  // the background
        if (it.isTileValue()) {
            openvdb::CoordBBox b;
            it.getBoundingBox(b);
            tree.fill(b, v, false);
        } else if (std::fabs(v) < frame.band) {
            acc.setValue(it.getCoord(), v);
        } else {
            acc.setValueOff(it.getCoord(), v);
        }
    }
    out->clip(toCoordBBox(frame.indexBox));
    tree.prune();
    return out;
}

void adoptLevelSet(const openvdb::FloatGrid& distance, const VolumeFrame& frame, const VolumeSource& source,
                   double seconds, VoxelizeResult& result) {
    Volume v;
    v.frame = frame;
    v.normalization = 1.0 / frame.voxelSize;  // f is the distance in model units
    v.boxOrigin = result.modelBox.origin;
    v.source = source;
    openvdb::FloatGrid::Ptr grid = levelSetToOurGrid(distance, frame);
    grid->setName(source.body);
    v.grid().grid = grid;
    result.normalization.scale = v.normalization;
    result.stats.voxels = frame.indexBox.volume();
    result.stats.leaves = grid->tree().leafCount();
    result.stats.seconds = seconds;
    result.volume = std::move(v);
}

VoxelizeResult levelSetFromScalar(const ScalarVolume& volume, const IsoSurfaceRequest& request) {
    VoxelizeResult result;
    const auto start = Clock::now();
    if (std::string why = checkResolutionAndBand(request.resolution, request.band); !why.empty()) {
        result.error = why;
        return result;
    }
    if (!volume.grid) {
        result.error = "no volume was read";
        return result;
    }
    if (!(request.iso > volume.minValue && request.iso < volume.maxValue) || !std::isfinite(request.iso)) {
        result.error = "the iso-value " + formatValue(request.iso) + " is outside the data's range (" +
                       formatValue(volume.minValue) + " to " + formatValue(volume.maxValue) +
                       "): it must lie strictly between the lowest and the highest sample";
        return result;
    }
    ensureOpenVdbInitialized();
    InsideField inside;
    if (std::string why = insideField(volume, request, inside); !why.empty()) {
        result.error = why;
        return result;
    }
    result.modelBox.origin = request.box ? BoxOrigin::Given : BoxOrigin::Sampled;
    result.modelBox.box = request.box ? *request.box : modelBoxOf(*inside.field, inside.inside);
    VolumeFrame frame;
    if (std::string why = makeFrame(result.modelBox.box, request.resolution, request.band, frame); !why.empty()) {
        result.error = why;
        return result;
    }
    // The band's voxels: the surface's area (a sample face for each surface
    // sample) in voxels, times the band's thickness, by whole 8^3 leaves.
    const openvdb::Vec3d spacing = inside.field->voxelSize();
    const double sampleFace = (spacing.x() * spacing.y() + spacing.y() * spacing.z() + spacing.x() * spacing.z()) / 3.0;
    const double area = static_cast<double>(inside.surfaceSamples) * sampleFace / (frame.voxelSize * frame.voxelSize);
    const double leaves = area / 64.0 * (std::ceil(2.0 * (static_cast<double>(frame.band) + 1.0) / 8.0) + 1.0);
    const auto needed = static_cast<std::uint64_t>(leaves * 512.0 * kBytesPerBandVoxel);
    result.stats.estimatedBytes = needed;
    if (std::string why = refuseIfTooBig("the level set of the scanned volume", request.resolution, needed,
                                         memoryLimit(request.memoryLimit), 2.0);
        !why.empty()) {
        result.error = why;
        return result;
    }
    // The iso-surface meshed (volumeToMesh, linear along the sample
    // edges) and its distance rebuilt at our voxel size, a voxel beyond the
    // band on each side so that the clamp, not the rebuild, ends it.
    const openvdb::math::Transform::Ptr xform = frameTransform(frame);
    const float width = frame.band + 1.0f;
    openvdb::FloatGrid::Ptr distance;
    try {
        distance = openvdb::tools::levelSetRebuild(*inside.field, 0.0f, width, width, xform.get());
    } catch (const std::exception& e) {
        result.error = std::string("the iso-surface could not be rebuilt as a level set: ") + e.what();
        return result;
    }
    adoptLevelSet(*distance, frame, request.source, std::chrono::duration<double>(Clock::now() - start).count(), result);
    return result;
}

}  // namespace hg::voxel
