// The recipe that makes content/gestures/weights.json (docs/gestures.md,
// "Retraining"): which generated strokes, how many, which seeds, the
// network's size and the training schedule. hg_gesture_train, the
// benchmark and the test that checks the committed file all train through
// here, so the three cannot drift apart.
#pragma once

#include <cstdint>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "garden/gesture/gesture_network.h"
#include "garden/gesture/gesture_recognizer.h"
#include "garden/gesture/stroke_generator.h"

namespace hg::garden {

struct GestureTrainingRecipe {
    int trainPerGesture = 2000;
    int trainNone = 6000;
    std::uint64_t trainSeed = 20220301;
    int hidden = 32;
    std::uint64_t initSeed = 7;
    TrainingOptions options;
    double threshold = 0.7;
    double minimumLength = 12.0;
};

// Held out from training: made from another seed, never trained on.
constexpr int kHeldOutPerGesture = 300;
constexpr int kHeldOutNone = 900;
constexpr std::uint64_t kHeldOutSeed = 99991;

std::vector<LabelledStroke> heldOutStrokes();

// Trains from the recipe alone (deterministic: same recipe, same weights).
GestureRecognizer trainGestureRecognizer(const GestureTrainingRecipe& recipe, double* finalLoss = nullptr);

// The recipe as the weights file's "training" object.
nlohmann::json recipeJson(const GestureTrainingRecipe& recipe);

}  // namespace hg::garden
