#include "frep/compiler/tape.h"

#include <sstream>

namespace hg::frep {

const char* opName(Op op) {
    switch (op) {
        case Op::X: return "x";
        case Op::Y: return "y";
        case Op::Z: return "z";
        case Op::Const: return "const";
        case Op::Add: return "add";
        case Op::Sub: return "sub";
        case Op::Mul: return "mul";
        case Op::Div: return "div";
        case Op::Neg: return "neg";
        case Op::Abs: return "abs";
        case Op::Sqrt: return "sqrt";
        case Op::Exp: return "exp";
        case Op::Log: return "log";
        case Op::Sin: return "sin";
        case Op::Cos: return "cos";
        case Op::Tan: return "tan";
        case Op::Atan: return "atan";
        case Op::Asin: return "asin";
        case Op::Acos: return "acos";
        case Op::Atan2: return "atan2";
        case Op::Pow: return "pow";
        case Op::Floor: return "floor";
        case Op::Ceil: return "ceil";
        case Op::Trunc: return "trunc";
        case Op::Sinh: return "sinh";
        case Op::Cosh: return "cosh";
        case Op::Tanh: return "tanh";
        case Op::Lt: return "lt";
        case Op::Le: return "le";
        case Op::Gt: return "gt";
        case Op::Ge: return "ge";
        case Op::EqEps: return "eq";
        case Op::NeEps: return "ne";
        case Op::And: return "and";
        case Op::Or: return "or";
        case Op::Not: return "not";
        case Op::Truthy: return "truthy";
        case Op::Select: return "select";
        case Op::Min: return "min";
        case Op::Max: return "max";
        case Op::Union: return "union";
        case Op::Intersect: return "intersect";
        case Op::Subtract: return "subtract";
        case Op::HfDiv: return "hf_div";
        case Op::HfPow: return "hf_pow";
        case Op::HfSqrt: return "hf_sqrt";
        case Op::HfLog: return "hf_log";
        case Op::HfLog10: return "hf_log10";
        case Op::HfAsin: return "hf_asin";
        case Op::HfAcos: return "hf_acos";
        case Op::HfTan: return "hf_tan";
        case Op::HfMod: return "hf_mod";
        case Op::Check: return "check";
        case Op::ConvSegment: return "conv_segment";
        case Op::ConvArc: return "conv_arc";
        case Op::SoftStep: return "soft_step";
        case Op::W: return "w";
    }
    return "?";
}

int opArity(Op op) {
    switch (op) {
        case Op::X: case Op::Y: case Op::Z: case Op::Const: case Op::W: return 0;
        case Op::Neg: case Op::Abs: case Op::Sqrt: case Op::Exp: case Op::Log: case Op::Sin:
        case Op::Cos: case Op::Tan: case Op::Atan: case Op::Asin: case Op::Acos: case Op::Floor:
        case Op::Ceil: case Op::Trunc: case Op::Sinh: case Op::Cosh: case Op::Tanh: case Op::Not:
        case Op::Truthy: case Op::HfSqrt: case Op::HfLog: case Op::HfLog10: case Op::HfAsin:
        case Op::HfAcos: case Op::HfTan: case Op::Check:
            return 1;
        case Op::Select: case Op::ConvSegment: case Op::ConvArc: case Op::SoftStep: return 3;
        default: return 2;
    }
}

std::uint32_t fusedParamCount(Op op) {
    switch (op) {
        case Op::ConvSegment: return kConvSegmentParams;
        case Op::ConvArc: return kConvArcParams;
        case Op::SoftStep: return kSoftStepParams;
        default: return 0;
    }
}

bool opCanFail(Op op) {
    switch (op) {
        case Op::HfDiv: case Op::HfPow: case Op::HfSqrt: case Op::HfLog: case Op::HfLog10:
        case Op::HfAsin: case Op::HfAcos: case Op::HfTan: case Op::HfMod: case Op::Check:
            return true;
        default: return false;
    }
}

bool Tape::canFail() const {
    for (const Instr& i : code)
        if (opCanFail(i.op)) return true;
    return false;
}

std::string Tape::dump() const {
    std::ostringstream s;
    for (size_t i = 0; i < code.size(); ++i) {
        const Instr& in = code[i];
        s << "r" << out[i] << " = " << opName(in.op);
        if (in.op == Op::Const) s << " " << in.imm;
        for (std::uint32_t r : {in.a, in.b, in.c})
            if (r != kNoReg) s << " r" << r;
        if (in.guard != kNoReg) s << " if r" << in.guard;
        s << "\n";
    }
    s << "result r" << result << "\n";
    return s.str();
}

}  // namespace hg::frep
