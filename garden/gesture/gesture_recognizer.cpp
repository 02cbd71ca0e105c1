#include "garden/gesture/gesture_recognizer.h"

#include "garden/gesture/stroke_features.h"

namespace hg::garden {

GestureResult GestureRecognizer::classify(const StrokePoints& points) const {
    GestureResult result;
    const std::vector<double> features = strokeLength(points) >= minimumLength ? strokeFeatures(points) : std::vector<double>{};
    const std::vector<double> p = features.empty() ? std::vector<double>{} : network.probabilities(features);
    if (p.size() != static_cast<std::size_t>(kGestureLabelCount)) {
        result.tooShort = true;
        result.confidence = 1.0;
        result.probabilities[static_cast<std::size_t>(labelIndex(GestureLabel::None))] = 1.0;
        return result;
    }
    std::size_t best = 0;
    for (std::size_t k = 0; k < p.size(); ++k) {
        result.probabilities[k] = p[k];
        if (p[k] > p[best]) best = k;
    }
    result.best = kGestureLabels[best];
    result.confidence = p[best];
    result.label = result.confidence >= threshold ? result.best : GestureLabel::None;
    return result;
}

}  // namespace hg::garden
