#include "garden/gesture/gesture_weights.h"

#include <cstdio>
#include <cstring>
#include <sstream>

#include <nlohmann/json.hpp>

#include "garden/gesture/gesture_json.h"
#include "garden/gesture/stroke_features.h"
#include "garden/gesture/stroke_file.h"

namespace hg::garden {

using json = nlohmann::json;

namespace {

constexpr const char* kFormat = "hypergarden gesture weights";
constexpr int kVersion = 1;

// Every array of the network in file order, with its name and length.
template <class Network, class F>
void forEachArray(Network& n, F f) {
    f("mean", n.mean, n.inputs);
    f("scale", n.scale, n.inputs);
    f("w1", n.w1, n.hidden * n.inputs);
    f("b1", n.b1, n.hidden);
    f("w2", n.w2, n.outputs * n.hidden);
    f("b2", n.b2, n.outputs);
}

// Rows of `width` numbers a line, so that the file diffs by neuron.
void writeArray(std::ostringstream& out, const std::vector<double>& values, std::size_t width) {
    out << "[";
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (i > 0) out << ",";
        out << (i % width == 0 ? "\n      " : " ") << json(values[i]).dump();
    }
    out << "\n    ]";
}

int readCount(const json& v, const std::string& path, int lo, int hi) {
    if (!v.is_number_integer() || v.get<long long>() < lo || v.get<long long>() > hi)
        throw GestureJsonError(path, "expected a whole number in [" + std::to_string(lo) + ", " + std::to_string(hi) +
                                         "], found " + v.dump());
    return v.get<int>();
}

const json& requireKey(const json& object, const char* key, const std::string& path) {
    auto it = object.find(key);
    if (it == object.end()) throw GestureJsonError(path, std::string("missing key '") + key + "'");
    return *it;
}

// Refuses a value that differs from what this build computes.
void expectCount(const json& object, const char* key, const std::string& path, int expected) {
    const int found = readCount(requireKey(object, key, path), path + "." + key, 0, 1 << 20);
    if (found != expected)
        throw GestureJsonError(path + "." + key, "is " + std::to_string(found) + " but this build's features need " +
                                                     std::to_string(expected) + " (retrain: scripts/train-gestures.sh)");
}

}  // namespace

std::uint64_t gestureNetworkChecksum(const GestureNetwork& network) {
    std::uint64_t h = 1469598103934665603ull;
    forEachArray(network, [&](const char*, const std::vector<double>& values, int) {
        for (double v : values) {
            std::uint64_t bits = 0;
            std::memcpy(&bits, &v, sizeof bits);
            for (int byte = 0; byte < 8; ++byte) {
                h ^= (bits >> (8 * byte)) & 0xFFu;
                h *= 1099511628211ull;
            }
        }
    });
    return h;
}

std::string checksumHex(std::uint64_t checksum) {
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(checksum));
    return text;
}

std::string writeGestureWeights(const GestureRecognizer& recognizer, const json& training) {
    const GestureNetwork& n = recognizer.network;
    json labels = json::array();
    for (GestureLabel l : kGestureLabels) labels.push_back(labelName(l));
    json trained = training;
    trained["checksum"] = checksumHex(gestureNetworkChecksum(n));
    std::ostringstream out;
    out << "{\n  \"format\": \"" << kFormat << "\",\n  \"version\": " << kVersion << ",\n";
    out << "  \"features\": {\"thinning\": " << json(kFeatureThinning).dump() << ", \"resample\": " << kFeatureResample
        << ", \"smoothing\": " << kFeatureSmoothing << ", \"segments\": " << kFeatureSegments
        << ", \"count\": " << kFeatureCount << "},\n";
    out << "  \"labels\": " << labels.dump() << ",\n";
    out << "  \"threshold\": " << json(recognizer.threshold).dump() << ",\n";
    out << "  \"minimum_length\": " << json(recognizer.minimumLength).dump() << ",\n";
    out << "  \"training\": " << trained.dump() << ",\n";
    out << "  \"network\": {\n    \"inputs\": " << n.inputs << ", \"hidden\": " << n.hidden << ", \"outputs\": " << n.outputs;
    forEachArray(n, [&](const char* name, const std::vector<double>& values, int) {
        out << ",\n    \"" << name << "\": ";
        const bool matrix = std::strcmp(name, "w1") == 0 || std::strcmp(name, "w2") == 0;
        writeArray(out, values, matrix ? static_cast<std::size_t>(std::strcmp(name, "w1") == 0 ? n.inputs : n.hidden) : 8);
    });
    out << "\n  }\n}\n";
    return out.str();
}

GestureRecognizer readGestureWeights(const std::string& text) {
    const json doc = parseGestureJson(text);
    requireGestureObject(doc, "$", {"format", "version", "features", "labels", "threshold", "minimum_length", "training", "network"});
    if (requireKey(doc, "format", "$") != kFormat)
        throw GestureJsonError("$.format", std::string("expected \"") + kFormat + "\"");
    expectCount(doc, "version", "$", kVersion);
    const json& features = requireKey(doc, "features", "$");
    requireGestureObject(features, "$.features", {"thinning", "resample", "smoothing", "segments", "count"});
    if (readGestureNumber(requireKey(features, "thinning", "$.features"), "$.features.thinning") != kFeatureThinning)
        throw GestureJsonError("$.features.thinning", "differs from this build's " + json(kFeatureThinning).dump() +
                                                          " (retrain: scripts/train-gestures.sh)");
    expectCount(features, "resample", "$.features", kFeatureResample);
    expectCount(features, "smoothing", "$.features", kFeatureSmoothing);
    expectCount(features, "segments", "$.features", kFeatureSegments);
    expectCount(features, "count", "$.features", kFeatureCount);
    json labels = json::array();
    for (GestureLabel l : kGestureLabels) labels.push_back(labelName(l));
    if (requireKey(doc, "labels", "$") != labels) throw GestureJsonError("$.labels", "expected " + labels.dump());

    GestureRecognizer r;
    r.threshold = readGestureNumber(requireKey(doc, "threshold", "$"), "$.threshold");
    if (r.threshold < 0.0 || r.threshold > 1.0) throw GestureJsonError("$.threshold", "expected a probability in [0, 1]");
    r.minimumLength = readGestureNumber(requireKey(doc, "minimum_length", "$"), "$.minimum_length");
    const json& net = requireKey(doc, "network", "$");
    requireGestureObject(net, "$.network", {"inputs", "hidden", "outputs", "mean", "scale", "w1", "b1", "w2", "b2"});
    GestureNetwork& n = r.network;
    expectCount(net, "inputs", "$.network", kFeatureCount);
    n.inputs = kFeatureCount;
    n.hidden = readCount(requireKey(net, "hidden", "$.network"), "$.network.hidden", 1, 4096);
    expectCount(net, "outputs", "$.network", kGestureLabelCount);
    n.outputs = kGestureLabelCount;
    forEachArray(n, [&](const char* name, std::vector<double>& values, int size) {
        const std::string path = std::string("$.network.") + name;
        const json& v = requireKey(net, name, "$.network");
        if (!v.is_array() || v.size() != static_cast<std::size_t>(size))
            throw GestureJsonError(path, "expected an array of " + std::to_string(size) + " numbers, found " + describeGestureJson(v));
        values.clear();
        for (std::size_t i = 0; i < v.size(); ++i) values.push_back(readGestureNumber(v[i], gestureJsonIndex(path, i)));
    });
    const json& training = requireKey(doc, "training", "$");
    if (!training.is_object()) throw GestureJsonError("$.training", "expected an object");
    auto checksum = training.find("checksum");
    if (checksum == training.end() || !checksum->is_string())
        throw GestureJsonError("$.training", "missing key 'checksum' (a string)");
    if (checksum->get<std::string>() != checksumHex(gestureNetworkChecksum(n)))
        throw GestureJsonError("$.training.checksum", "does not match the weights (the file was changed by hand?)");
    return r;
}

GestureRecognizer loadGestureWeights(const std::string& path) {
    try {
        return readGestureWeights(readGestureTextFile(path));
    } catch (const GestureJsonError& e) {
        if (e.path() == path) throw;
        throw GestureJsonError(path + ": " + e.path(), e.reason());
    }
}

}  // namespace hg::garden
