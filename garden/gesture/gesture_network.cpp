#include "garden/gesture/gesture_network.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "garden/gesture/gesture_random.h"

namespace hg::garden {

namespace {

// The hidden layer's activations for standardized inputs `x`.
void forwardHidden(const GestureNetwork& n, const std::vector<double>& x, std::vector<double>& h) {
    h.assign(static_cast<std::size_t>(n.hidden), 0.0);
    for (int j = 0; j < n.hidden; ++j) {
        const double* row = &n.w1[static_cast<std::size_t>(j * n.inputs)];
        double s = n.b1[static_cast<std::size_t>(j)];
        for (int i = 0; i < n.inputs; ++i) s += row[i] * x[static_cast<std::size_t>(i)];
        h[static_cast<std::size_t>(j)] = std::tanh(s);
    }
}

void forwardOutput(const GestureNetwork& n, const std::vector<double>& h, std::vector<double>& p) {
    p.assign(static_cast<std::size_t>(n.outputs), 0.0);
    double top = -1e300;
    for (int k = 0; k < n.outputs; ++k) {
        const double* row = &n.w2[static_cast<std::size_t>(k * n.hidden)];
        double s = n.b2[static_cast<std::size_t>(k)];
        for (int j = 0; j < n.hidden; ++j) s += row[j] * h[static_cast<std::size_t>(j)];
        p[static_cast<std::size_t>(k)] = s;
        top = std::max(top, s);
    }
    double sum = 0.0;
    for (double& v : p) { v = std::exp(v - top); sum += v; }
    for (double& v : p) v /= sum;
}

std::vector<double> standardize(const GestureNetwork& n, const std::vector<double>& features) {
    std::vector<double> x(features.size());
    for (std::size_t i = 0; i < features.size(); ++i) x[i] = (features[i] - n.mean[i]) * n.scale[i];
    return x;
}

void setStandardization(GestureNetwork& n, const std::vector<TrainingExample>& examples) {
    const std::size_t inputs = static_cast<std::size_t>(n.inputs);
    n.mean.assign(inputs, 0.0);
    n.scale.assign(inputs, 1.0);
    if (examples.empty()) return;
    const double count = static_cast<double>(examples.size());
    for (const TrainingExample& e : examples)
        for (std::size_t i = 0; i < inputs; ++i) n.mean[i] += e.features[i];
    for (double& m : n.mean) m /= count;
    std::vector<double> variance(inputs, 0.0);
    for (const TrainingExample& e : examples)
        for (std::size_t i = 0; i < inputs; ++i) variance[i] += (e.features[i] - n.mean[i]) * (e.features[i] - n.mean[i]);
    // A feature that never varies would divide by zero; leave it at unit scale.
    for (std::size_t i = 0; i < inputs; ++i) {
        const double sigma = std::sqrt(variance[i] / count);
        n.scale[i] = sigma > 1e-9 ? 1.0 / sigma : 1.0;
    }
}

}  // namespace

std::vector<double> GestureNetwork::probabilities(const std::vector<double>& features) const {
    std::vector<double> p;
    if (features.size() != static_cast<std::size_t>(inputs)) return p;
    std::vector<double> h;
    forwardHidden(*this, standardize(*this, features), h);
    forwardOutput(*this, h, p);
    return p;
}

GestureNetwork makeGestureNetwork(int inputs, int hidden, int outputs, GestureRandom& random) {
    GestureNetwork n;
    n.inputs = inputs;
    n.hidden = hidden;
    n.outputs = outputs;
    n.mean.assign(static_cast<std::size_t>(inputs), 0.0);
    n.scale.assign(static_cast<std::size_t>(inputs), 1.0);
    const double r1 = std::sqrt(6.0 / (inputs + hidden)), r2 = std::sqrt(6.0 / (hidden + outputs));
    n.w1.resize(static_cast<std::size_t>(hidden * inputs));
    for (double& w : n.w1) w = random.uniform(-r1, r1);
    n.b1.assign(static_cast<std::size_t>(hidden), 0.0);
    n.w2.resize(static_cast<std::size_t>(outputs * hidden));
    for (double& w : n.w2) w = random.uniform(-r2, r2);
    n.b2.assign(static_cast<std::size_t>(outputs), 0.0);
    return n;
}

double trainGestureNetwork(GestureNetwork& n, const std::vector<TrainingExample>& examples, const TrainingOptions& options) {
    setStandardization(n, examples);
    std::vector<std::vector<double>> inputs;
    inputs.reserve(examples.size());
    for (const TrainingExample& e : examples) inputs.push_back(standardize(n, e.features));

    const std::size_t in = static_cast<std::size_t>(n.inputs), hid = static_cast<std::size_t>(n.hidden),
                      out = static_cast<std::size_t>(n.outputs);
    std::vector<double> gw1(n.w1.size()), gb1(hid), gw2(n.w2.size()), gb2(out);
    std::vector<double> vw1(n.w1.size(), 0.0), vb1(hid, 0.0), vw2(n.w2.size(), 0.0), vb2(out, 0.0);
    std::vector<double> h, p, deltaOut(out), deltaHidden(hid);
    std::vector<std::size_t> order(examples.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    GestureRandom shuffle(options.shuffleSeed);
    double epochLoss = 0.0;

    for (int epoch = 0; epoch < options.epochs; ++epoch) {
        // Fisher-Yates with our generator: the same order everywhere.
        for (std::size_t i = order.size(); i > 1; --i) std::swap(order[i - 1], order[shuffle.below(i)]);
        const double progress = options.epochs > 1 ? static_cast<double>(epoch) / (options.epochs - 1) : 0.0;
        const double rate = options.learningRate * (1.0 - 0.95 * progress);
        epochLoss = 0.0;
        for (std::size_t start = 0; start < order.size(); start += static_cast<std::size_t>(options.batch)) {
            const std::size_t end = std::min(order.size(), start + static_cast<std::size_t>(options.batch));
            std::fill(gw1.begin(), gw1.end(), 0.0);
            std::fill(gb1.begin(), gb1.end(), 0.0);
            std::fill(gw2.begin(), gw2.end(), 0.0);
            std::fill(gb2.begin(), gb2.end(), 0.0);
            for (std::size_t s = start; s < end; ++s) {
                const std::vector<double>& x = inputs[order[s]];
                const std::size_t label = static_cast<std::size_t>(examples[order[s]].label);
                forwardHidden(n, x, h);
                forwardOutput(n, h, p);
                epochLoss -= std::log(std::max(p[label], 1e-300));
                // Softmax with cross-entropy: the output error is p - target.
                for (std::size_t k = 0; k < out; ++k) deltaOut[k] = p[k] - (k == label ? 1.0 : 0.0);
                for (std::size_t j = 0; j < hid; ++j) {
                    double back = 0.0;
                    for (std::size_t k = 0; k < out; ++k) back += n.w2[k * hid + j] * deltaOut[k];
                    deltaHidden[j] = back * (1.0 - h[j] * h[j]);  // tanh' = 1 - tanh^2
                }
                for (std::size_t k = 0; k < out; ++k) {
                    gb2[k] += deltaOut[k];
                    for (std::size_t j = 0; j < hid; ++j) gw2[k * hid + j] += deltaOut[k] * h[j];
                }
                for (std::size_t j = 0; j < hid; ++j) {
                    gb1[j] += deltaHidden[j];
                    for (std::size_t i = 0; i < in; ++i) gw1[j * in + i] += deltaHidden[j] * x[i];
                }
            }
            const double perExample = 1.0 / static_cast<double>(end - start);
            auto step = [&](std::vector<double>& w, std::vector<double>& g, std::vector<double>& v, bool decay) {
                for (std::size_t i = 0; i < w.size(); ++i) {
                    const double grad = g[i] * perExample + (decay ? options.weightDecay * w[i] : 0.0);
                    v[i] = options.momentum * v[i] - rate * grad;
                    w[i] += v[i];
                }
            };
            step(n.w1, gw1, vw1, true);
            step(n.b1, gb1, vb1, false);
            step(n.w2, gw2, vw2, true);
            step(n.b2, gb2, vb2, false);
        }
        epochLoss /= static_cast<double>(std::max<std::size_t>(1, examples.size()));
    }
    return epochLoss;
}

}  // namespace hg::garden
