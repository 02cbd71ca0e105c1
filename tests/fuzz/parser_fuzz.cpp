// libFuzzer target for the HyperFun front end: any input must parse or fail
// with diagnostics, without crashing, hanging or undefined behaviour, and a
// program that parses must be a well-formed AST (every slot, body index,
// library id and argument list the evaluators rely on is valid).
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "frep/kernels/library/library.h"
#include "frep/language/parser.h"

using namespace hg::frep;

namespace {

void check(bool ok) {
    if (!ok) std::abort();
}

void checkExpr(const Expr& e, const Program& p, size_t bodyIndex, int depth) {
    const Body& b = p.bodies[bodyIndex];
    check(depth <= ParseLimits::kMaxTreeDepth);
    check(e.loc.line >= 1 && e.loc.column >= 1);
    auto arraySlot = [&](int slot) { return slot >= 0 && static_cast<size_t>(slot) < b.arrays.size(); };
    switch (e.kind) {
        case ExprKind::Number: check(e.args.empty()); break;
        case ExprKind::Variable:
            check(e.args.empty());
            check(e.slot >= 0 && static_cast<size_t>(e.slot) < b.variables.size());
            break;
        case ExprKind::ArrayElement: check(e.args.size() == 1 && arraySlot(e.slot)); break;
        case ExprKind::ArrayName: check(e.args.empty() && arraySlot(e.slot)); break;
        case ExprKind::Unary: check(e.args.size() == 1); break;
        case ExprKind::Binary: check(e.args.size() == 2); break;
        case ExprKind::BuiltinCall: {
            bool two = e.builtin == Builtin::Mod || e.builtin == Builtin::Max ||
                       e.builtin == Builtin::Min || e.builtin == Builtin::Atan2;
            check(e.args.size() == (two ? 2u : 1u));
            for (const auto& a : e.args) check(a->kind != ExprKind::ArrayName);
            break;
        }
        case ExprKind::LibraryCall: {
            check(e.function >= 0 && static_cast<size_t>(e.function) < lib::functions().size());
            const auto& params = lib::functions()[static_cast<size_t>(e.function)].params;
            check(e.args.size() == params.size());
            for (size_t i = 0; i < params.size(); ++i)
                check((params[i] == lib::ParamKind::Array) ==
                      (e.args[i]->kind == ExprKind::ArrayName));
            break;
        }
        case ExprKind::BodyCall: {
            check(e.function >= 0 && static_cast<size_t>(e.function) < bodyIndex);
            const Body& callee = p.bodies[static_cast<size_t>(e.function)];
            check(e.args.size() == 2 || e.args.size() == 3);
            for (const auto& a : e.args) check(a->kind == ExprKind::ArrayName);
            int sizes[3] = {callee.xSize(), callee.aSize(), callee.sSize()};
            for (size_t i = 0; i < e.args.size(); ++i)
                check(b.arrays[static_cast<size_t>(e.args[i]->slot)].size == sizes[i]);
            if (e.args.size() == 2) check(callee.sSize() == 1);
            break;
        }
    }
    for (const auto& a : e.args) {
        check(a != nullptr);
        checkExpr(*a, p, bodyIndex, depth + 1);
    }
}

void checkStmts(const std::vector<Stmt>& stmts, const Program& p, size_t bodyIndex) {
    const Body& b = p.bodies[bodyIndex];
    for (const Stmt& s : stmts) {
        switch (s.kind) {
            case StmtKind::Assign:
                check(s.slot >= 0 && static_cast<size_t>(s.slot) < b.variables.size());
                check(s.value != nullptr);
                checkExpr(*s.value, p, bodyIndex, 1);
                break;
            case StmtKind::AssignElement:
                check(s.slot >= 2 && static_cast<size_t>(s.slot) < b.arrays.size());
                check(s.index && s.value);
                checkExpr(*s.index, p, bodyIndex, 1);
                checkExpr(*s.value, p, bodyIndex, 1);
                break;
            case StmtKind::AssignArray:
                check(s.slot >= 2 && static_cast<size_t>(s.slot) < b.arrays.size());
                check(s.literal.size() == static_cast<size_t>(b.arrays[static_cast<size_t>(s.slot)].size));
                break;
            case StmtKind::If:
            case StmtKind::While:
                check(s.condition != nullptr);
                checkExpr(*s.condition, p, bodyIndex, 1);
                if (s.kind == StmtKind::While) check(s.elseBody.empty());
                checkStmts(s.thenBody, p, bodyIndex);
                checkStmts(s.elseBody, p, bodyIndex);
                break;
        }
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::string_view source(reinterpret_cast<const char*>(data), size);
    ParseResult r = parseProgram(source, "fuzz.hf");
    check(r.ok() == r.errors.empty());
    check(r.program.has_value() == r.errors.empty());
    check(r.errors.size() <= static_cast<size_t>(ParseLimits::kMaxErrors) + 1);
    for (const Diagnostic& d : r.errors) {
        check(!d.message.empty());
        check(d.loc.line >= 1 && d.loc.column >= 1);
        check(d.sourceLine.size() < 1000);
        std::string text = formatDiagnostic(d);
        check(!text.empty());
    }
    if (r.program) {
        const Program& p = *r.program;
        check(!p.bodies.empty());
        check(p.defaultBody() >= 0 && static_cast<size_t>(p.defaultBody()) < p.bodies.size());
        for (size_t i = 0; i < p.bodies.size(); ++i) {
            const Body& b = p.bodies[i];
            check(b.arrays.size() >= 3);
            check(p.findBody(b.name) == static_cast<int>(i));
            if (!b.declaresS) check(b.sSize() == 1);
            for (const auto& a : b.arrays) check(a.size >= 0 && a.size <= ParseLimits::kMaxArraySize);
            for (size_t k = 3; k < b.arrays.size(); ++k) check(b.arrays[k].size >= 1);
            check(b.result != nullptr);
            checkExpr(*b.result, p, i, 1);
            checkStmts(b.statements, p, i);
        }
    }
    return 0;
}
