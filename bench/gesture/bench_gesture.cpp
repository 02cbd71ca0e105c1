// Gesture recognition benchmark (issue 22, docs/gestures.md): the committed
// weights' accuracy on the held-out generated strokes and on the committed
// hand-like set, the time to classify one stroke (features and network
// apart), and the time to train the weights from the recipe. Prints
// Markdown tables; --json FILE writes the rows too. --filter classify or
// --filter train runs only that part (the accuracy tables always print).
//
//   ./build/release/bench/bench_gesture [--json out.json] [--filter NAME] [--repeat N]
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "../bench_common.h"

#include "garden/gesture/gesture_evaluation.h"
#include "garden/gesture/gesture_json.h"
#include "garden/gesture/gesture_training.h"
#include "garden/gesture/gesture_weights.h"
#include "garden/gesture/stroke_features.h"
#include "garden/gesture/stroke_file.h"

namespace {

using namespace hg;
using namespace hg::garden;

std::vector<LabelledStroke> handLike(const std::string& path) {
    std::vector<LabelledStroke> out;
    for (const FileStroke& s : readStrokeFile(readGestureTextFile(path)))
        if (s.label) out.push_back({s.points, *s.label});
    return out;
}

}  // namespace

int main(int argc, char** argv) {
    bench::BenchArgs args;
    if (!bench::parseBenchArgs(argc, argv, args)) return 2;
    const std::string content = std::string(HG_SOURCE_DIR) + "/content/gestures/";
    GestureRecognizer r;
    std::vector<LabelledStroke> hand;
    try {
        r = loadGestureWeights(content + "weights.json");
        hand = handLike(content + "handlike.json");
    } catch (const GestureJsonError& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return 1;
    }
    const std::vector<LabelledStroke> heldOut = heldOutStrokes();
    nlohmann::json rows = nlohmann::json::array();

    std::printf("| set | strokes | gestures right | none taken for a gesture | all right |\n|---|---:|---:|---:|---:|\n");
    const std::pair<const char*, const std::vector<LabelledStroke>*> sets[] = {{"held out (generated)", &heldOut},
                                                                               {"hand-like", &hand}};
    for (const auto& [name, set] : sets) {
        ConfusionTable t;
        for (const LabelledStroke& s : *set) t.add(s.label, r.classify(s.points).label);
        std::printf("| %s | %d | %.2f%% of %d | %.2f%% of %d | %.2f%% |\n", name, t.total(), 100.0 * t.gestureAccuracy(),
                    t.gestures(), 100.0 * t.falseGestureRate(), t.nones(), 100.0 * t.accuracy());
        rows.push_back({{"set", name}, {"strokes", t.total()}, {"gesture_accuracy", t.gestureAccuracy()},
                        {"false_gesture_rate", t.falseGestureRate()}, {"accuracy", t.accuracy()}});
        std::printf("\n```\n%s```\n\n", t.format().c_str());
    }

    if (args.matches("classify")) {
        // Over every held-out stroke, so that short and long strokes mix as
        // they come; the points per stroke are the generator's (12 to 450).
        std::size_t points = 0;
        for (const LabelledStroke& s : heldOut) points += s.points.size();
        double sink = 0.0;
        const double whole = bench::bestOf(args.repeat, [&] {
            for (const LabelledStroke& s : heldOut) sink += r.classify(s.points).confidence;
        });
        const double features = bench::bestOf(args.repeat, [&] {
            for (const LabelledStroke& s : heldOut) sink += strokeFeatures(s.points)[0];
        });
        std::vector<std::vector<double>> described;
        for (const LabelledStroke& s : heldOut) described.push_back(strokeFeatures(s.points));
        const double network = bench::bestOf(args.repeat, [&] {
            for (const std::vector<double>& f : described) sink += r.network.probabilities(f)[0];
        });
        const double n = static_cast<double>(heldOut.size());
        std::printf("| classify one stroke (us) | features (us) | network (us) | mean points per stroke |\n|---:|---:|---:|---:|\n");
        std::printf("| %.1f | %.1f | %.1f | %.0f |\n\n", 1e6 * whole / n, 1e6 * features / n, 1e6 * network / n,
                    static_cast<double>(points) / n);
        rows.push_back({{"classify_us", 1e6 * whole / n}, {"features_us", 1e6 * features / n}, {"network_us", 1e6 * network / n},
                        {"checksum", sink}});
    }

    if (args.matches("train")) {
        const GestureTrainingRecipe recipe;
        GestureRecognizer trained;
        const double seconds = bench::bestOf(1, [&] { trained = trainGestureRecognizer(recipe); });
        const bool same = gestureNetworkChecksum(trained.network) == gestureNetworkChecksum(r.network);
        const int strokes = 6 * recipe.trainPerGesture + recipe.trainNone;
        std::printf("| training strokes | epochs | hidden | training, 1 thread (s) | same as committed |\n|---:|---:|---:|---:|---|\n");
        std::printf("| %d | %d | %d | %.2f | %s |\n", strokes, recipe.options.epochs, recipe.hidden, seconds, same ? "yes" : "NO");
        rows.push_back({{"training_strokes", strokes}, {"training_s", seconds}, {"same_as_committed", same}});
    }
    if (!args.jsonPath.empty()) std::ofstream(args.jsonPath) << rows.dump(2) << "\n";
    return 0;
}
