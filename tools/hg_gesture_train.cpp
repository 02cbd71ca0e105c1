// hg_gesture_train: rebuilds the gesture recognizer's weights from the
// repository alone (docs/gestures.md, "Retraining"); scripts/train-gestures.sh
// runs it. Deterministic: the same build writes the same file every time.
//
//   hg_gesture_train -o content/gestures/weights.json [--check FILE.json]...
//
// Prints the held-out accuracy and confusion table, and the same for every
// --check file of labelled strokes (the committed hand-like set).
#include <chrono>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "garden/gesture/gesture_evaluation.h"
#include "garden/gesture/gesture_json.h"
#include "garden/gesture/gesture_training.h"
#include "garden/gesture/gesture_weights.h"
#include "garden/gesture/stroke_file.h"

namespace {

using namespace hg::garden;

void report(const char* name, const ConfusionTable& t) {
    std::printf("%s: %d strokes, gestures right %.2f%% (%d), none taken for a gesture %.2f%% (%d)\n%s\n", name, t.total(),
                100.0 * t.gestureAccuracy(), t.gestures(), 100.0 * t.falseGestureRate(), t.nones(), t.format().c_str());
}

// How the threshold trades missed gestures for false ones, to choose it.
void thresholdTable(const GestureRecognizer& r, const std::vector<LabelledStroke>& strokes) {
    std::printf("threshold  gestures right  none taken for a gesture\n");
    std::vector<GestureResult> results;
    for (const LabelledStroke& s : strokes) results.push_back(r.classify(s.points));
    for (double threshold : {0.0, 0.5, 0.6, 0.7, 0.8, 0.9, 0.95}) {
        ConfusionTable t;
        for (std::size_t i = 0; i < strokes.size(); ++i)
            t.add(strokes[i].label, results[i].confidence >= threshold ? results[i].best : GestureLabel::None);
        std::printf("%9.2f  %13.2f%%  %23.2f%%\n", threshold, 100.0 * t.gestureAccuracy(), 100.0 * t.falseGestureRate());
    }
    std::printf("\n");
}

}  // namespace

int main(int argc, char** argv) {
    std::string output;
    std::vector<std::string> checks;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if ((arg == "-o" || arg == "--output") && i + 1 < argc) output = argv[++i];
        else if (arg == "--check" && i + 1 < argc) checks.push_back(argv[++i]);
        else {
            std::fprintf(stderr, "usage: %s -o WEIGHTS.json [--check STROKES.json]...\n", argv[0]);
            return 2;
        }
    }
    if (output.empty()) {
        std::fprintf(stderr, "error: -o WEIGHTS.json is required\n");
        return 2;
    }
    const GestureTrainingRecipe recipe;
    const auto t0 = std::chrono::steady_clock::now();
    double loss = 0.0;
    const GestureRecognizer r = trainGestureRecognizer(recipe, &loss);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("trained in %.2f s, final loss %.5f, checksum %s\n\n", seconds, loss,
                checksumHex(gestureNetworkChecksum(r.network)).c_str());

    const std::vector<LabelledStroke> heldOut = heldOutStrokes();
    ConfusionTable held;
    for (const LabelledStroke& s : heldOut) held.add(s.label, r.classify(s.points).label);
    report("held out (generated, another seed)", held);
    thresholdTable(r, heldOut);
    for (const std::string& path : checks) {
        try {
            std::vector<LabelledStroke> labelled;
            ConfusionTable t;
            for (const FileStroke& s : readStrokeFile(readGestureTextFile(path))) {
                if (!s.label) continue;
                t.add(*s.label, r.classify(s.points).label);
                labelled.push_back({s.points, *s.label});
            }
            report(path.c_str(), t);
            thresholdTable(r, labelled);
        } catch (const GestureJsonError& e) {
            std::fprintf(stderr, "error: %s: %s\n", path.c_str(), e.what());
            return 1;
        }
    }

    std::ofstream out(output, std::ios::binary | std::ios::trunc);
    out << writeGestureWeights(r, recipeJson(recipe));
    out.close();
    if (!out) {
        std::fprintf(stderr, "error: cannot write %s\n", output.c_str());
        return 1;
    }
    std::printf("wrote %s\n", output.c_str());
    return 0;
}
