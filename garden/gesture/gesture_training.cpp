#include "garden/gesture/gesture_training.h"

#include <nlohmann/json.hpp>

#include "garden/gesture/gesture_random.h"
#include "garden/gesture/stroke_features.h"

namespace hg::garden {

std::vector<LabelledStroke> heldOutStrokes() { return generateStrokeSet(kHeldOutPerGesture, kHeldOutNone, kHeldOutSeed); }

GestureRecognizer trainGestureRecognizer(const GestureTrainingRecipe& recipe, double* finalLoss) {
    std::vector<TrainingExample> examples;
    for (const LabelledStroke& s : generateStrokeSet(recipe.trainPerGesture, recipe.trainNone, recipe.trainSeed)) {
        std::vector<double> f = strokeFeatures(s.points);
        if (f.empty()) continue;  // a degenerate stroke teaches nothing
        examples.push_back({std::move(f), labelIndex(s.label)});
    }
    GestureRandom init(recipe.initSeed);
    GestureRecognizer r;
    r.network = makeGestureNetwork(kFeatureCount, recipe.hidden, kGestureLabelCount, init);
    const double loss = trainGestureNetwork(r.network, examples, recipe.options);
    if (finalLoss) *finalLoss = loss;
    r.threshold = recipe.threshold;
    r.minimumLength = recipe.minimumLength;
    return r;
}

nlohmann::json recipeJson(const GestureTrainingRecipe& recipe) {
    const TrainingOptions& o = recipe.options;
    return {{"generator_seed", recipe.trainSeed},
            {"strokes_per_gesture", recipe.trainPerGesture},
            {"none_strokes", recipe.trainNone},
            {"init_seed", recipe.initSeed},
            {"shuffle_seed", o.shuffleSeed},
            {"epochs", o.epochs},
            {"batch", o.batch},
            {"learning_rate", o.learningRate},
            {"momentum", o.momentum},
            {"weight_decay", o.weightDecay}};
}

}  // namespace hg::garden
