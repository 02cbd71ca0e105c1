// The network written here: back-propagation's gradient agrees with finite
// differences, it learns a problem no linear model can, and training is
// deterministic.
#include <gtest/gtest.h>

#include <cmath>

#include "garden/gesture/gesture_network.h"
#include "garden/gesture/gesture_random.h"
#include "garden/gesture/gesture_weights.h"

namespace hg::garden {
namespace {

double loss(const GestureNetwork& n, const std::vector<TrainingExample>& examples) {
    double sum = 0.0;
    for (const TrainingExample& e : examples) sum -= std::log(n.probabilities(e.features)[static_cast<std::size_t>(e.label)]);
    return sum / static_cast<double>(examples.size());
}

std::vector<TrainingExample> xorExamples() {
    std::vector<TrainingExample> e;
    GestureRandom r(3);
    for (int i = 0; i < 200; ++i) {
        const double a = r.uniform(-1.0, 1.0), b = r.uniform(-1.0, 1.0);
        e.push_back({{a, b}, (a > 0.0) != (b > 0.0) ? 1 : 0});
    }
    return e;
}

TEST(GestureNetwork, OneStepOfBackPropagationFollowsTheGradient) {
    // With momentum 0, no decay and one batch of everything, one epoch is one
    // gradient step: each weight moves by -rate * dLoss/dw, which finite
    // differences of the loss must agree with.
    const std::vector<TrainingExample> examples = xorExamples();
    GestureRandom init(5);
    GestureNetwork before = makeGestureNetwork(2, 4, 2, init);
    TrainingOptions o;
    o.epochs = 1;
    o.batch = static_cast<int>(examples.size());
    o.momentum = 0.0;
    o.weightDecay = 0.0;
    o.learningRate = 1e-3;
    GestureNetwork after = before;
    trainGestureNetwork(after, examples, o);
    before.mean = after.mean;  // the standardization training sets
    before.scale = after.scale;
    for (std::size_t i = 0; i < before.w1.size(); ++i) {
        GestureNetwork plus = before, minus = before;
        plus.w1[i] += 1e-6;
        minus.w1[i] -= 1e-6;
        const double gradient = (loss(plus, examples) - loss(minus, examples)) / 2e-6;
        EXPECT_NEAR((after.w1[i] - before.w1[i]) / -o.learningRate, gradient, 1e-5) << "w1[" << i << "]";
    }
    for (std::size_t i = 0; i < before.w2.size(); ++i) {
        GestureNetwork plus = before, minus = before;
        plus.w2[i] += 1e-6;
        minus.w2[i] -= 1e-6;
        const double gradient = (loss(plus, examples) - loss(minus, examples)) / 2e-6;
        EXPECT_NEAR((after.w2[i] - before.w2[i]) / -o.learningRate, gradient, 1e-5) << "w2[" << i << "]";
    }
}

TEST(GestureNetwork, LearnsExclusiveOrAndTrainsTheSameEveryTime) {
    const std::vector<TrainingExample> examples = xorExamples();
    TrainingOptions o;
    o.epochs = 300;
    o.batch = 8;
    o.learningRate = 0.1;
    auto train = [&] {
        GestureRandom init(11);
        GestureNetwork n = makeGestureNetwork(2, 8, 2, init);
        trainGestureNetwork(n, examples, o);
        return n;
    };
    const GestureNetwork a = train(), b = train();
    int right = 0;
    for (const TrainingExample& e : examples) {
        const std::vector<double> p = a.probabilities(e.features);
        right += (p[1] > p[0]) == (e.label == 1);
    }
    EXPECT_GE(right, 190);
    EXPECT_EQ(gestureNetworkChecksum(a), gestureNetworkChecksum(b));
}

TEST(GestureNetwork, AWrongSizedInputHasNoAnswer) {
    GestureRandom init(1);
    const GestureNetwork n = makeGestureNetwork(3, 4, 2, init);
    EXPECT_TRUE(n.probabilities({1.0, 2.0}).empty());
    const std::vector<double> p = n.probabilities({1.0, 2.0, 3.0});
    ASSERT_EQ(p.size(), 2u);
    EXPECT_NEAR(p[0] + p[1], 1.0, 1e-12);
}

}  // namespace
}  // namespace hg::garden
