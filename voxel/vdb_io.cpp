#include "voxel/vdb_io.h"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>

#include <openvdb/io/Stream.h>
#include <openvdb/tools/LevelSetRebuild.h>

#include "io/checked_write.h"
#include "voxel/vdb_grids.h"
#include "voxel/volume_vdb.h"

namespace hg::voxel {

namespace {

constexpr int kFormatVersion = 1;

std::string numberList(const std::vector<double>& values) {
    std::string s;
    char buf[32];
    for (size_t i = 0; i < values.size(); ++i) {
        std::snprintf(buf, sizeof buf, "%.17g", values[i]);
        if (i) s += ',';
        s += buf;
    }
    return s;
}

std::vector<double> parseList(const std::string& s) {
    std::vector<double> out;
    std::stringstream in(s);
    std::string item;
    while (std::getline(in, item, ',')) out.push_back(std::strtod(item.c_str(), nullptr));
    return out;
}

void addMetadata(openvdb::GridBase& grid, const Volume& v) {
    const VolumeFrame& f = v.frame;
    grid.insertMeta(meta::kFormat, openvdb::Int32Metadata(kFormatVersion));
    grid.insertMeta(meta::kKind, openvdb::StringMetadata(v.kind == VolumeKind::NarrowBand ? "narrow-band" : "dense-source"));
    grid.insertMeta(meta::kSourceFile, openvdb::StringMetadata(v.source.file));
    grid.insertMeta(meta::kBody, openvdb::StringMetadata(v.source.body));
    grid.insertMeta(meta::kParameters, openvdb::StringMetadata(numberList(v.source.parameters)));
    grid.insertMeta(meta::kNormalization, openvdb::DoubleMetadata(v.normalization));
    grid.insertMeta(meta::kBand, openvdb::FloatMetadata(f.band));
    grid.insertMeta(meta::kResolution, openvdb::Int32Metadata(f.resolution));
    grid.insertMeta(meta::kModelBoxMin, openvdb::Vec3DMetadata(openvdb::Vec3d(f.modelBox.lo[0], f.modelBox.lo[1], f.modelBox.lo[2])));
    grid.insertMeta(meta::kModelBoxMax, openvdb::Vec3DMetadata(openvdb::Vec3d(f.modelBox.hi[0], f.modelBox.hi[1], f.modelBox.hi[2])));
    grid.insertMeta(meta::kBoxEstimated, openvdb::BoolMetadata(v.boxOrigin != BoxOrigin::Given));
    grid.insertMeta(meta::kBoxOrigin, openvdb::StringMetadata(boxOriginName(v.boxOrigin)));
    grid.insertMeta(meta::kIndexMin, openvdb::Vec3IMetadata(openvdb::Vec3i(f.indexBox.lo[0], f.indexBox.lo[1], f.indexBox.lo[2])));
    grid.insertMeta(meta::kIndexMax, openvdb::Vec3IMetadata(openvdb::Vec3i(f.indexBox.hi[0], f.indexBox.hi[1], f.indexBox.hi[2])));
}

// The grid as the bytes of a .vdb file (OpenVDB's stream format, which
// openvdb::io::File reads), so that the caller writes them with every step
// checked (io/checked_write.h): OpenVDB's own file writer does not report
// a full disk.
std::string encodeGrid(const openvdb::GridBase::Ptr& grid, std::string& bytes) {
    ensureOpenVdbInitialized();
    try {
        std::ostringstream out(std::ios::binary);
        openvdb::io::Stream(out).write(openvdb::GridPtrVec{grid});
        bytes = out.str();
    } catch (const std::exception& e) {
        return std::string("cannot encode the grid: ") + e.what();
    }
    return "";
}

std::string writeGrid(const openvdb::GridBase::Ptr& grid, const std::string& path, io::WriteSite site) {
    if (std::string why = io::checkWritable(path); !why.empty()) return why;
    std::string bytes;
    if (std::string why = encodeGrid(grid, bytes); !why.empty()) return "cannot write " + path + ": " + why;
    return io::writeFileAtomically(path, bytes, site);
}

openvdb::FloatGrid::Ptr ourGrid(const Volume& volume) {
    // Shares the (unchanged) tree; the metadata added below is the copy's own.
    openvdb::FloatGrid::Ptr grid = std::const_pointer_cast<openvdb::FloatGrid>(vdb(volume).copy());
    addMetadata(*grid, volume);
    grid->insertMeta(meta::kSign, openvdb::StringMetadata("positive inside (HyperFun); values in voxels"));
    grid->setGridClass(openvdb::GRID_UNKNOWN);
    return grid;
}

template <class T, class M>
bool readMeta(const openvdb::GridBase& grid, const char* key, T& out) {
    auto m = grid.getMetadata<M>(key);
    if (!m) return false;
    out = m->value();
    return true;
}

}  // namespace

std::string writeVolume(const Volume& volume, const std::string& path, io::WriteSite site) {
    return writeGrid(ourGrid(volume), path, site);
}

std::string encodeVolume(const Volume& volume, std::string& bytes) { return encodeGrid(ourGrid(volume), bytes); }

std::string writeLevelSet(const Volume& volume, const std::string& path, double metresPerUnit) {
    // Our values are f scaled to about one unit per voxel, not distances;
    // other tools expect a signed distance field. Flip the sign and scale
    // to model units, then turn it into true distances.
    const double h = volume.frame.voxelSize;
    openvdb::FloatGrid::Ptr flipped = vdb(volume).deepCopy();
    const float scale = static_cast<float>(-h);
    for (auto it = flipped->tree().beginValueAll(); it; ++it) it.setValue(*it * scale);
    flipped->tree().root().setBackground(static_cast<float>(static_cast<double>(volume.frame.band) * h), false);
    flipped->setGridClass(openvdb::GRID_LEVEL_SET);
    // Rebuilding through a mesh (OpenVDB's own volumeToMesh and
    // meshToVolume) gives exact distances to the same zero surface; fast
    // sweeping leaves |grad| off 1 near thin parts.
    const float band = std::max(3.0f, volume.frame.band);
    openvdb::FloatGrid::Ptr grid;
    try {
        grid = openvdb::tools::levelSetRebuild(*flipped, 0.0f, band, band);
    } catch (const std::exception& e) {
        return "cannot convert the grid to a level set: " + std::string(e.what());
    }
    grid->setName(flipped->getName());
    addMetadata(*grid, volume);
    if (metresPerUnit > 0.0) {
        const float m = static_cast<float>(metresPerUnit);
        for (auto it = grid->tree().beginValueAll(); it; ++it) it.setValue(*it * m);
        grid->tree().root().setBackground(grid->background() * m, false);
        grid->transform().postScale(metresPerUnit);
        grid->insertMeta(meta::kSign, openvdb::StringMetadata("negative inside (OpenVDB level set); signed distance in metres"));
    } else {
        grid->insertMeta(meta::kSign, openvdb::StringMetadata("negative inside (OpenVDB level set); signed distance in model units"));
    }
    grid->setGridClass(openvdb::GRID_LEVEL_SET);
    return writeGrid(grid, path, io::WriteSite::Export);
}

std::string readVdbGrids(const std::string& path, openvdb::GridPtrVecPtr& grids) {
    ensureOpenVdbInitialized();
    try {
        openvdb::io::File file(path);
        file.open();
        grids = file.getGrids();
        file.close();
    } catch (const std::exception& e) {
        return "cannot read " + path + ": " + e.what();
    }
    return "";
}

std::string readVolume(const std::string& path, Volume& volume, const std::string& gridName) {
    openvdb::GridPtrVecPtr grids;
    if (std::string why = readVdbGrids(path, grids); !why.empty()) return why;
    for (const openvdb::GridBase::Ptr& base : *grids) {
        if (!gridName.empty() && base->getName() != gridName) continue;
        int format = 0;
        if (!readMeta<int, openvdb::Int32Metadata>(*base, meta::kFormat, format)) continue;
        if (format != kFormatVersion)
            return path + ": grid '" + base->getName() + "' has Hypergarden format " + std::to_string(format) +
                   "; this build reads format " + std::to_string(kFormatVersion);
        openvdb::FloatGrid::Ptr grid = openvdb::gridPtrCast<openvdb::FloatGrid>(base);
        if (!grid) return path + ": grid '" + base->getName() + "' is not a float grid";
        if (grid->getGridClass() == openvdb::GRID_LEVEL_SET)
            return path + ": grid '" + base->getName() +
                   "' is a level-set export (negative inside); read the Hypergarden grid it was exported from";
        Volume v;
        VolumeFrame& f = v.frame;
        std::string kind, params;
        bool boxEstimated = false;
        openvdb::Vec3d lo, hi;
        openvdb::Vec3i ilo, ihi;
        bool ok = readMeta<std::string, openvdb::StringMetadata>(*grid, meta::kKind, kind) &&
                  readMeta<std::string, openvdb::StringMetadata>(*grid, meta::kSourceFile, v.source.file) &&
                  readMeta<std::string, openvdb::StringMetadata>(*grid, meta::kBody, v.source.body) &&
                  readMeta<std::string, openvdb::StringMetadata>(*grid, meta::kParameters, params) &&
                  readMeta<double, openvdb::DoubleMetadata>(*grid, meta::kNormalization, v.normalization) &&
                  readMeta<float, openvdb::FloatMetadata>(*grid, meta::kBand, f.band) &&
                  readMeta<int, openvdb::Int32Metadata>(*grid, meta::kResolution, f.resolution) &&
                  readMeta<openvdb::Vec3d, openvdb::Vec3DMetadata>(*grid, meta::kModelBoxMin, lo) &&
                  readMeta<openvdb::Vec3d, openvdb::Vec3DMetadata>(*grid, meta::kModelBoxMax, hi) &&
                  readMeta<bool, openvdb::BoolMetadata>(*grid, meta::kBoxEstimated, boxEstimated) &&
                  readMeta<openvdb::Vec3i, openvdb::Vec3IMetadata>(*grid, meta::kIndexMin, ilo) &&
                  readMeta<openvdb::Vec3i, openvdb::Vec3IMetadata>(*grid, meta::kIndexMax, ihi);
        if (!ok) return path + ": grid '" + base->getName() + "' lacks some Hypergarden metadata";
        v.kind = kind == "dense-source" ? VolumeKind::DenseSource : VolumeKind::NarrowBand;
        v.source.parameters = parseList(params);
        // Grids written before the sampled fallback have no origin: their
        // found boxes were all interval estimates.
        v.boxOrigin = boxEstimated ? BoxOrigin::IntervalEstimate : BoxOrigin::Given;
        std::string origin;
        if (readMeta<std::string, openvdb::StringMetadata>(*grid, meta::kBoxOrigin, origin))
            for (BoxOrigin o : {BoxOrigin::Given, BoxOrigin::IntervalEstimate, BoxOrigin::Sampled})
                if (origin == boxOriginName(o)) v.boxOrigin = o;
        for (int a = 0; a < 3; ++a) {
            f.modelBox.lo[a] = lo[a];
            f.modelBox.hi[a] = hi[a];
            f.indexBox.lo[a] = ilo[a];
            f.indexBox.hi[a] = ihi[a];
        }
        f.voxelSize = grid->voxelSize()[0];
        v.grid().grid = grid;
        volume = std::move(v);
        return "";
    }
    if (!gridName.empty()) return path + ": no Hypergarden grid named '" + gridName + "'";
    return path + ": no Hypergarden grid in the file (written by another program?)";
}

}  // namespace hg::voxel
