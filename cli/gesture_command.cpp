// `hypergarden gesture FILE.json [--json] [--weights W] [--threshold T]`:
// classifies each stroke of a stroke file with the gesture recognizer
// (docs/gestures.md) and, where strokes carry labels, prints the accuracy
// and the confusion table. The weights come from the content folder next
// to the default garden (content/gestures/weights.json), as the garden
// itself does.
#include <cstdio>
#include <filesystem>
#include <iostream>

#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "garden/gesture/gesture_evaluation.h"
#include "garden/gesture/gesture_json.h"
#include "garden/gesture/gesture_weights.h"
#include "garden/gesture/stroke_file.h"

namespace hg::garden::cli {

namespace {

std::string defaultWeights() {
    // HG_DEFAULT_GARDEN is content/gardens/default.json.
    return (std::filesystem::path(HG_DEFAULT_GARDEN).parent_path().parent_path() / "gestures" / "weights.json").string();
}

std::string percent(double share) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2f%%", 100.0 * share);
    return text;
}

std::string fixed(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3f", v);
    return text;
}

nlohmann::json confusionJson(const ConfusionTable& t) {
    nlohmann::json labels = nlohmann::json::array(), rows = nlohmann::json::array();
    for (GestureLabel l : kGestureLabels) labels.push_back(labelName(l));
    for (const auto& row : t.counts) rows.push_back(row);
    return {{"labels", labels}, {"counts", rows}};
}

}  // namespace

int runGestureCommand(const GestureCommandOptions& options) {
    const std::string weightsPath = options.weights.empty() ? defaultWeights() : options.weights;
    GestureRecognizer recognizer;
    std::vector<FileStroke> strokes;
    try {
        recognizer = loadGestureWeights(weightsPath);
    } catch (const GestureJsonError& e) {
        std::cerr << "error: gesture weights " << e.what() << "\n";
        return 1;
    }
    try {
        strokes = readStrokeFile(readGestureTextFile(options.file));
    } catch (const GestureJsonError& e) {
        std::cerr << "error: " << (e.path() == options.file ? std::string(e.what()) : options.file + ": " + e.what()) << "\n";
        return 1;
    }
    if (options.threshold >= 0.0) recognizer.threshold = options.threshold;

    ConfusionTable table;
    nlohmann::json results = nlohmann::json::array();
    for (std::size_t i = 0; i < strokes.size(); ++i) {
        const FileStroke& s = strokes[i];
        const GestureResult r = recognizer.classify(s.points);
        if (s.label) table.add(*s.label, r.label);
        if (options.json) {
            nlohmann::json probabilities = nlohmann::json::object();
            for (GestureLabel l : kGestureLabels)
                probabilities[labelName(l)] = r.probabilities[static_cast<std::size_t>(labelIndex(l))];
            nlohmann::json item = {{"stroke", i + 1}, {"label", labelName(r.label)}, {"confidence", r.confidence},
                                   {"best", labelName(r.best)}, {"too_short", r.tooShort}, {"probabilities", probabilities}};
            if (s.label) item["truth"] = labelName(*s.label);
            results.push_back(item);
            continue;
        }
        std::string line = "stroke " + std::to_string(i + 1) + ": " + labelName(r.label) + " " + fixed(r.confidence);
        if (r.tooShort)
            line += " (too short to be a gesture)";
        else if (r.label != r.best)
            line += std::string(" (") + labelName(r.best) + " below the threshold " + fixed(recognizer.threshold) + ")";
        if (s.label && *s.label == r.label) line += "  right";
        else if (s.label) line += std::string("  WRONG, truth ") + labelName(*s.label);
        std::cout << line << "\n";
    }
    if (options.json) {
        nlohmann::json out = {
            {"file", options.file}, {"weights", weightsPath}, {"threshold", recognizer.threshold}, {"strokes", results}};
        if (table.total() > 0)
            out["summary"] = {{"labelled", table.total()},
                              {"correct", table.correct()},
                              {"accuracy", table.accuracy()},
                              {"gestures", table.gestures()},
                              {"gesture_accuracy", table.gestureAccuracy()},
                              {"nones", table.nones()},
                              {"false_gesture_rate", table.falseGestureRate()},
                              {"confusion", confusionJson(table)}};
        std::cout << out.dump(2) << "\n";
        return 0;
    }
    if (strokes.empty()) std::cout << "no strokes in " << options.file << "\n";
    if (table.total() > 0) {
        std::cout << "\naccuracy: " << table.correct() << " of " << table.total() << " labelled strokes right ("
                  << percent(table.accuracy()) << ")\n";
        if (table.gestures() > 0)
            std::cout << "gestures right: " << percent(table.gestureAccuracy()) << " of " << table.gestures() << "\n";
        if (table.nones() > 0)
            std::cout << "none taken for a gesture: " << percent(table.falseGestureRate()) << " of " << table.nones() << "\n";
        std::cout << "\n" << table.format();
    }
    return 0;
}

}  // namespace hg::garden::cli
