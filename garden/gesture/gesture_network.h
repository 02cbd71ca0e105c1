// The seed's classifier: a feed-forward network with one hidden layer
// (tanh) and a softmax output, trained by back-propagation (mini-batch
// gradient descent with momentum on the cross-entropy). Written here rather
// than taken from a library so that training is deterministic and the
// committed weights can be rebuilt bit for bit: one thread, a fixed order
// of operations and our own random numbers (gesture_random.h).
#pragma once

#include <cstdint>
#include <vector>

namespace hg::garden {

class GestureRandom;

struct GestureNetwork {
    int inputs = 0, hidden = 0, outputs = 0;
    // Features are standardized first: (x - mean) * scale, from the
    // training set, so that the extras and the sines train at one rate.
    std::vector<double> mean, scale;       // inputs each
    std::vector<double> w1, b1;            // hidden x inputs (row-major), hidden
    std::vector<double> w2, b2;            // outputs x hidden, outputs

    // Softmax probabilities, one per output (empty when the input size is
    // wrong).
    std::vector<double> probabilities(const std::vector<double>& features) const;
};

// Small random weights (Glorot uniform), unit standardization.
GestureNetwork makeGestureNetwork(int inputs, int hidden, int outputs, GestureRandom& random);

struct TrainingExample {
    std::vector<double> features;
    int label = 0;
};

struct TrainingOptions {
    int epochs = 60;
    int batch = 32;
    double learningRate = 0.05;     // at the start; falls linearly to 5% of it by the last epoch
    double momentum = 0.9;
    double weightDecay = 1e-4;      // L2, against over-confident weights
    std::uint64_t shuffleSeed = 1;
};

// Sets the standardization from `examples`, then trains. Returns the mean
// cross-entropy of the last epoch.
double trainGestureNetwork(GestureNetwork& network, const std::vector<TrainingExample>& examples,
                           const TrainingOptions& options);

}  // namespace hg::garden
