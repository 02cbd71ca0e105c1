#include "frep/eval/model.h"

#include <sstream>

#include "frep/compiler/compiler.h"
#include "frep/eval/eval_batch.h"
#include "frep/language/interpreter.h"

namespace hg::frep {

Model::Model(std::shared_ptr<const Program> program, int body, std::vector<double> a)
    : program_(std::move(program)), body_(body), a_(std::move(a)) {
    CompileResult c = compile(*program_, body_, a_);
    if (c.tape) tape_ = std::move(c.tape);
    reason_ = c.reason;
    reasonLoc_ = c.reasonLoc;
}

std::string Model::pathDescription() const {
    std::ostringstream s;
    if (tape_) {
        s << "tape (" << tape_->size() << " instructions, " << tape_->registers << " registers)";
    } else {
        s << "scalar interpreter: " << reason_;
        if (reasonLoc_.line > 0) s << " (line " << reasonLoc_.line << ", column " << reasonLoc_.column << ")";
    }
    return s.str();
}

template <class T>
struct PointSampler<T>::Impl {
    std::unique_ptr<BatchEvaluator<T>> batch;
    std::unique_ptr<Interpreter> interp;
};

template <class T>
PointSampler<T>::PointSampler(const Model& model) : impl_(std::make_unique<Impl>()) {
    if (model.tape()) impl_->batch = std::make_unique<BatchEvaluator<T>>(*model.tape());
    else impl_->interp = std::make_unique<Interpreter>(model.program(), model.bodyIndex(), model.parameters());
}

template <class T>
PointSampler<T>::~PointSampler() = default;

template <class T>
void PointSampler<T>::evaluate(const T* x, const T* y, const T* z, T* out, size_t n, ErrorReport& errors,
                               std::uint8_t* failed) {
    if (impl_->batch) {
        impl_->batch->evaluate(x, y, z, out, n, errors, failed);
        return;
    }
    for (size_t i = 0; i < n; ++i) {
        std::uint64_t before = errors.count;
        out[i] = static_cast<T>(impl_->interp->evaluateSafe(static_cast<double>(x[i]), static_cast<double>(y[i]),
                                                            static_cast<double>(z[i]), errors));
        if (failed) failed[i] = errors.count != before;
    }
}

template class PointSampler<float>;
template class PointSampler<double>;

}  // namespace hg::frep
