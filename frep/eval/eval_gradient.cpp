#include "frep/eval/eval_gradient.h"

#include <algorithm>
#include <cmath>

#include "frep/compiler/conv_kernels.h"
#include "frep/compiler/op_semantics.h"

namespace hg::frep {

GradientEvaluator::GradientEvaluator(const Tape& tape)
    : tape_(&tape),
      v_(static_cast<size_t>(tape.registers) * kBatch),
      dx_(v_.size()), dy_(v_.size()), dz_(v_.size()), fail_(kBatch) {}

void GradientEvaluator::rebind(const Tape& tape) {
    tape_ = &tape;
    const size_t n = static_cast<size_t>(tape.registers) * kBatch;
    if (v_.size() < n) {
        v_.resize(n);
        dx_.resize(n);
        dy_.resize(n);
        dz_.resize(n);
    }
}

Gradient GradientEvaluator::evaluate(double x, double y, double z, ErrorReport& errors) {
    Gradient g;
    evaluate(&x, &y, &z, &g, 1, errors);
    return g;
}

void GradientEvaluator::evaluate(const double* x, const double* y, const double* z, Gradient* out, size_t n,
                                 ErrorReport& errors) {
    for (size_t i = 0; i < n; i += kBatch)
        chunk(x + i, y + i, z + i, out + i, std::min(kBatch, n - i), errors);
}

void GradientEvaluator::chunk(const double* x, const double* y, const double* z, Gradient* out, size_t n,
                              ErrorReport& errors) {
    std::fill_n(fail_.data(), n, 0);
    DomainError firstError = DomainError::None;
    SourceLoc firstLoc;
    for (size_t k = 0; k < tape_->code.size(); ++k) {
        const Instr& in = tape_->code[k];
        const size_t o = static_cast<size_t>(tape_->out[k]) * kBatch;
        const size_t a = in.a != kNoReg ? static_cast<size_t>(in.a) * kBatch : 0;
        const size_t b = in.b != kNoReg ? static_cast<size_t>(in.b) * kBatch : 0;
        const size_t c = in.c != kNoReg ? static_cast<size_t>(in.c) * kBatch : 0;
        for (size_t i = 0; i < n; ++i) {
            const double av = in.a != kNoReg ? v_[a + i] : 0.0;
            const double bv = in.b != kNoReg ? v_[b + i] : 0.0;
            const double cv = in.c != kNoReg ? v_[c + i] : 0.0;
            double value = 0.0;
            double ka = 0.0, kb = 0.0;
            DomainError e = applyOp<double>(in.op, in.error, av, bv, cv, value);
            if (in.op == Op::X) value = x[i];
            if (in.op == Op::Y) value = y[i];
            if (in.op == Op::Z) value = z[i];
            if (in.op == Op::Const) value = in.imm;
            double kc = 0.0;  // coefficient of c's derivative (fused kernels)
            if (fusedParamCount(in.op) > 0) {
                // The kernel's own closed form, differentiated analytically.
                double slope[3];
                value = fusedGradient(in.op, av, bv, cv, tape_->params.data() + in.param, slope);
                ka = slope[0]; kb = slope[1]; kc = slope[2];
            }
            if (e != DomainError::None && (in.guard == kNoReg || v_[static_cast<size_t>(in.guard) * kBatch + i] != 0.0)) {
                if (!fail_[i] && firstError == DomainError::None) {
                    firstError = e;
                    firstLoc = tape_->sites[in.site];
                }
                fail_[i] = 1;
            }
            // d(out) = da * ka + db * kb (+ dc * kc); select/min/max pick one.
            int pick = 0;  // select/min/max: 1 takes a's derivative, 2 b's, 3 c's
            switch (in.op) {
                case Op::X: case Op::Y: case Op::Z: case Op::Const: break;
                case Op::Add: ka = 1; kb = 1; break;
                case Op::Sub: ka = 1; kb = -1; break;
                case Op::Mul: ka = bv; kb = av; break;
                case Op::Div: case Op::HfDiv: ka = 1.0 / bv; kb = -av / (bv * bv); break;
                case Op::Neg: ka = -1; break;
                case Op::Abs: ka = av < 0 ? -1 : 1; break;
                case Op::Sqrt: case Op::HfSqrt: ka = value > 0 ? 0.5 / value : 0.0; break;
                case Op::Exp: ka = value; break;
                case Op::Log: case Op::HfLog: ka = 1.0 / av; break;
                case Op::HfLog10: ka = 1.0 / (av * std::log(10.0)); break;
                case Op::Sin: ka = std::cos(av); break;
                case Op::Cos: ka = -std::sin(av); break;
                case Op::Tan: case Op::HfTan: { double cs = std::cos(av); ka = 1.0 / (cs * cs); break; }
                case Op::Atan: ka = 1.0 / (1.0 + av * av); break;
                case Op::Asin: case Op::HfAsin: ka = 1.0 / std::sqrt(std::max(1e-300, 1.0 - av * av)); break;
                case Op::Acos: case Op::HfAcos: ka = -1.0 / std::sqrt(std::max(1e-300, 1.0 - av * av)); break;
                case Op::Atan2: { double r2 = av * av + bv * bv; if (r2 > 0) { ka = bv / r2; kb = -av / r2; } break; }
                case Op::Pow: case Op::HfPow:
                    if (av != 0.0) {
                        ka = bv * value / av;
                        kb = av > 0 ? value * std::log(av) : 0.0;
                    }
                    break;
                case Op::Sinh: ka = std::cosh(av); break;
                case Op::Cosh: ka = std::sinh(av); break;
                case Op::Tanh: ka = 1.0 - value * value; break;
                case Op::Select: pick = av != 0.0 ? 2 : 3; break;
                case Op::Min: pick = av < bv ? 1 : 2; break;
                case Op::Max: pick = av > bv ? 1 : 2; break;
                case Op::Union: case Op::Intersect: case Op::Subtract: {
                    double g = in.op == Op::Subtract ? -bv : bv;
                    double s = std::sqrt(av * av + g * g);
                    double sign = in.op == Op::Union ? 1.0 : -1.0;
                    ka = 1.0 + (s > 0 ? sign * av / s : 0.0);
                    double kg = 1.0 + (s > 0 ? sign * g / s : 0.0);
                    kb = in.op == Op::Subtract ? -kg : kg;
                    break;
                }
                case Op::Check: ka = 1; break;
                case Op::ConvSegment: case Op::ConvArc: case Op::SoftStep: break;  // coefficients computed above
                default: break;  // floor, comparisons, logic, mod: piecewise constant
            }
            double gx, gy, gz;
            if (in.op == Op::X) { gx = 1; gy = 0; gz = 0; }
            else if (in.op == Op::Y) { gx = 0; gy = 1; gz = 0; }
            else if (in.op == Op::Z) { gx = 0; gy = 0; gz = 1; }
            else if (pick) {
                size_t s = pick == 1 ? a : pick == 2 ? b : c;
                gx = dx_[s + i]; gy = dy_[s + i]; gz = dz_[s + i];
            } else {
                gx = gy = gz = 0.0;
                if (ka != 0.0) { gx += ka * dx_[a + i]; gy += ka * dy_[a + i]; gz += ka * dz_[a + i]; }
                if (kb != 0.0) { gx += kb * dx_[b + i]; gy += kb * dy_[b + i]; gz += kb * dz_[b + i]; }
                if (kc != 0.0) { gx += kc * dx_[c + i]; gy += kc * dy_[c + i]; gz += kc * dz_[c + i]; }
            }
            v_[o + i] = value;
            dx_[o + i] = gx; dy_[o + i] = gy; dz_[o + i] = gz;
        }
    }
    const size_t r = static_cast<size_t>(tape_->result) * kBatch;
    std::uint64_t failures = 0;
    for (size_t i = 0; i < n; ++i) {
        Gradient g{v_[r + i], dx_[r + i], dy_[r + i], dz_[r + i]};
        bool bad = fail_[i] || !std::isfinite(g.dx) || !std::isfinite(g.dy) || !std::isfinite(g.dz) || std::isnan(g.value);
        if (fail_[i] || std::isnan(g.value)) {
            if (firstError == DomainError::None) firstError = DomainError::NotANumber;
            ++failures;
            g = Gradient{kOutsideValue, 0, 0, 0};
        } else if (bad) {
            g.dx = g.dy = g.dz = 0.0;  // derivative undefined here (a kink at a pole)
        }
        g.value = std::min(std::max(g.value, -kValueLimit), kValueLimit);
        out[i] = g;
    }
    if (failures) errors.add(firstError, firstLoc, failures);
}

}  // namespace hg::frep
