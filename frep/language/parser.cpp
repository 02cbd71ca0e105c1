// Recursive descent over the reference interpreter's grammar. The structure
// follows int_parse_N.c function by function (HF_Get_Expression, HF_For_Sum,
// HF_For_Mult, HF_For_Power, HF_Get_Bool_Expr, HF_For_Compare, HF_For_Bool,
// HF_Parse_Operators, HF_Get_Array_Decl, HF_Get_Body_Def, HF_Get_X_A,
// HF_parse) so that the same token is examined at the same point and the
// same first error comes out; the code is our own.
#include "frep/language/parser.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <unordered_map>
#include <utility>

#include "frep/language/lexer.h"
#include "frep/kernels/library/library.h"

namespace hg::frep {

namespace {

using syntax::Token;
using TK = syntax::TokenKind;

// The reference's Error_Strings (int_global.c) used by the parser.
namespace msg {
constexpr const char* kBodyNameExpected = "Body name expected";
constexpr const char* kBodyNameNotUnique = "Body name is not unique";
constexpr const char* kLeftParenExpected = "Left parenthes expected";
constexpr const char* kXExpected = "\"X\" expected";
constexpr const char* kLeftBracketExpected = "Left bracket expected";
constexpr const char* kRealNumberExpected = "Real number expected";
constexpr const char* kArraySizeGreaterZero = "Array size must be greater zero";
constexpr const char* kRightBracketExpected = "Right bracket expected";
constexpr const char* kCommaExpected = "Comma expected";
constexpr const char* kAExpected = "\"A\" expected";
constexpr const char* kSExpected = "\"S\" expected";
constexpr const char* kRightParenExpected = "Right parenthes expected";
constexpr const char* kLeftBraceExpected = "Left brace expected";
constexpr const char* kAssignMarkExpected = "Assign mark expected";
constexpr const char* kSemicolonExpected = "Semicolon expected";
constexpr const char* kArgumentError = "Error in argument in function call";
constexpr const char* kWrongNumberOfItems = "Wrong number of items in array";
constexpr const char* kOnlyArrayName = "Only array name expected";
constexpr const char* kThenExpected = "Reserved word \"then\" expected";
constexpr const char* kEndIfExpected = "Reserved word \"endif\" expected";
constexpr const char* kElseEndIfExpected = "Reserved words \"else\" or \"endif\" expected";
constexpr const char* kLoopExpected = "Reserved word \"loop\" expected";
constexpr const char* kEndLoopExpected = "Reserved word \"endloop\" expected";
constexpr const char* kIdentifierExpected = "Identifier expected";
constexpr const char* kRightBraceExpected = "Right brace expected";
constexpr const char* kUnassignedIdentifier = "Unassigned identificator used in expression";
constexpr const char* kExpressionExpected = "Expression expected";
constexpr const char* kLeftBracketOrAssign = "Left bracket or assign mark expected";
}  // namespace msg

using Limits = ParseLimits;

// The reference's HF_round: nearest integer, halves up.
double hfRound(double d) {
    double c = std::ceil(d);
    return (c - d > 0.5) ? c - 1.0 : c;
}

constexpr Builtin kBuiltinByReferenceIndex[syntax::kBuiltinCount] = {
    Builtin::Sqrt, Builtin::Exp,  Builtin::Log,  Builtin::Logd,  Builtin::Sin,  Builtin::Cos,
    Builtin::Tan,  Builtin::Asin, Builtin::Acos, Builtin::Atan,  Builtin::Abs,  Builtin::Sinh,
    Builtin::Cosh, Builtin::Tanh, Builtin::Sign, Builtin::Mod,   Builtin::Max,  Builtin::Min,
    Builtin::Atan2, Builtin::Ceil, Builtin::Floor, Builtin::Int, Builtin::Frac,
};

bool isArrayToken(TK k) {
    return k == TK::Identifier || k == TK::XId || k == TK::AId || k == TK::SId;
}

// An expression under construction with the height of its tree.
struct Node {
    ExprPtr e;
    int h = 0;
};

struct NameInfo {
    bool isArray = false;
    int slot = -1;
};

class Parser {
public:
    Parser(std::string_view source, const std::string& file) : lex_(source), file_(file) {}

    ParseResult run();

private:
    // RAII nesting counter; reports once when the limit is passed.
    struct Nest {
        explicit Nest(Parser& p) : parser(p) {
            ok = ++parser.depth_ <= Limits::kMaxNesting;
            if (!ok)
                parser.error(parser.tok_, "nesting too deep: more than " +
                                              std::to_string(Limits::kMaxNesting) +
                                              " levels of parentheses, operators, calls or "
                                              "if/while");
        }
        ~Nest() { --parser.depth_; }
        Nest(const Nest&) = delete;
        Nest& operator=(const Nest&) = delete;
        Parser& parser;
        bool ok = true;
    };

    // --- tokens and errors ---
    void advance() {
        if (aborted_) {
            tok_.kind = TK::End;
            return;
        }
        tok_ = lex_.next();
    }
    bool is(TK k) const { return tok_.kind == k; }
    std::string text(const Token& t) const {
        return std::string(lex_.source().substr(t.offset, t.length));
    }
    void error(const Token& at, const std::string& message, std::string note = {});
    void fatal(const Token& at, const std::string& message) {
        error(at, message);
        aborted_ = true;
        tok_.kind = TK::End;
    }
    void skipToSemicolon() {
        advance();
        while (!is(TK::End) && !is(TK::Semicolon)) advance();
    }
    ExprPtr newExpr(ExprKind kind, const Token& t);
    void countNodes(size_t n, const Token& at) {
        nodes_ += n;
        if (nodes_ > Limits::kMaxNodes && !aborted_)
            fatal(at, "program too large: more than " + std::to_string(Limits::kMaxNodes) +
                          " syntax nodes");
    }

    // --- expressions ---
    bool parseExpression(Node& out);   // HF_Get_Expression: + - @ & | '\'
    bool parseTerm(Node& out);         // HF_For_Sum: * /
    bool parsePowerLevel(Node& out);   // HF_For_Mult: ^
    bool parseFactor(Node& out);       // HF_For_Power
    bool parseCondition(Node& out);    // HF_Get_Bool_Expr: and or
    bool parseComparison(Node& out);   // HF_For_Compare: = /= < <= > >=
    bool parseBoolOperand(Node& out);  // HF_For_Bool: not, ( condition ), expression
    bool parseBodyCall(Node& out);
    bool parseRoutineCall(Node& out);
    bool parseElement(Node& out, const Token& name, int slot);
    bool binary(const Token& op, Node& left, Node& right);
    bool unary(const Token& op, UnaryOp kind, Node& operand, Node& out);
    bool tooDeep(int h, const Token& at);
    bool resolveArray(const Token& t, int& slot) const;
    bool bodyCallArgument(Expr& call, int expectedSize, const char* what, const Body& callee,
                          Token& bad, bool& hasBad);

    // --- statements ---
    bool parseStatements(std::vector<Stmt>& out);  // HF_Parse_Operators; true if errors
    bool parseIf(std::vector<Stmt>& out);
    bool parseWhile(std::vector<Stmt>& out);
    bool parseAssign(std::vector<Stmt>& out, int slot);
    bool parseElementAssign(std::vector<Stmt>& out, const Token& name, int slot);
    bool parseArrayLiteral(std::vector<Stmt>& out, const Token& name, int slot);
    void parseArrayDecl();
    bool parseParams(Body& b);
    bool parseParamSize(int& size);
    bool parseBodyDef(Body& b);
    int addVariable(const Token& t);

    syntax::Lexer lex_;
    std::string file_;
    Token tok_;
    std::vector<Diagnostic> errors_;
    bool aborted_ = false;
    Program program_;
    std::unordered_map<std::string, int> bodyIndex_;
    Body* body_ = nullptr;  // the body being parsed
    std::unordered_map<std::string, NameInfo> names_;
    long long bodyArrayItems_ = 0;
    int depth_ = 0;
    size_t nodes_ = 0;
    // "Unassigned identificator" errors, to explain calls of later bodies.
    struct Unresolved {
        size_t error;
        std::string name;
        std::string caller;
    };
    void explainUnresolved();
    std::vector<Unresolved> unresolved_;
};

void Parser::error(const Token& at, const std::string& message, std::string note) {
    if (aborted_) return;
    if (static_cast<int>(errors_.size()) >= Limits::kMaxErrors) {
        errors_.push_back(makeDiagnostic(file_, lex_.source(), at.offset, at.loc,
                                         "too many errors; parsing stopped"));
        aborted_ = true;
        tok_.kind = TK::End;
        return;
    }
    if (note.empty() && at.kind == TK::Illegal) note = syntax::describe(at, lex_.source());
    errors_.push_back(
        makeDiagnostic(file_, lex_.source(), at.offset, at.loc, message, std::move(note)));
}

ExprPtr Parser::newExpr(ExprKind kind, const Token& t) {
    countNodes(1, t);
    auto e = std::make_unique<Expr>();
    e->kind = kind;
    e->loc = t.loc;
    e->spelling = text(t);
    return e;
}

// ---------------------------------------------------------------------------
// Expressions

bool Parser::binary(const Token& op, Node& left, Node& right) {
    int h = std::max(left.h, right.h) + 1;
    if (tooDeep(h, op)) return false;
    BinaryOp kind = BinaryOp::Add;
    switch (op.kind) {
        case TK::Plus: kind = BinaryOp::Add; break;
        case TK::Minus: kind = BinaryOp::Sub; break;
        case TK::Star: kind = BinaryOp::Mul; break;
        case TK::Slash: kind = BinaryOp::Div; break;
        case TK::Power: kind = BinaryOp::Pow; break;
        case TK::Union: kind = BinaryOp::Union; break;
        case TK::Ampersand: kind = BinaryOp::Intersection; break;
        case TK::At: kind = BinaryOp::Intersection; break;
        case TK::Backslash: kind = BinaryOp::Difference; break;
        case TK::Assign: kind = BinaryOp::Equal; break;
        case TK::NotEqual: kind = BinaryOp::NotEqual; break;
        case TK::Less: kind = BinaryOp::Less; break;
        case TK::LessEqual: kind = BinaryOp::LessEqual; break;
        case TK::Greater: kind = BinaryOp::Greater; break;
        case TK::GreaterEqual: kind = BinaryOp::GreaterEqual; break;
        case TK::And: kind = BinaryOp::And; break;
        case TK::Or: kind = BinaryOp::Or; break;
        default: break;
    }
    ExprPtr e = newExpr(ExprKind::Binary, op);
    e->binaryOp = kind;
    e->args.reserve(2);
    e->args.push_back(std::move(left.e));
    e->args.push_back(std::move(right.e));
    left.e = std::move(e);
    left.h = h;
    return true;
}

bool Parser::tooDeep(int h, const Token& at) {
    if (h <= Limits::kMaxTreeDepth) return false;
    error(at, "expression too long: more than " + std::to_string(Limits::kMaxTreeDepth) +
                  " levels of operators; split it into several assignments");
    return true;
}

bool Parser::unary(const Token& op, UnaryOp kind, Node& operand, Node& out) {
    if (tooDeep(operand.h + 1, op)) return false;
    ExprPtr e = newExpr(ExprKind::Unary, op);
    e->unaryOp = kind;
    e->args.push_back(std::move(operand.e));
    out.e = std::move(e);
    out.h = operand.h + 1;
    return true;
}

bool Parser::parseExpression(Node& out) {
    Nest nest(*this);
    if (!nest.ok) return false;
    Node left;
    if (!parseTerm(left)) return false;
    while (is(TK::Plus) || is(TK::Minus) || is(TK::At) || is(TK::Ampersand) ||
           is(TK::Union) || is(TK::Backslash)) {
        Token op = tok_;
        advance();
        Node right;
        if (!parseTerm(right)) return false;
        if (!binary(op, left, right)) return false;
    }
    out = std::move(left);
    return true;
}

bool Parser::parseTerm(Node& out) {
    Node left;
    if (!parsePowerLevel(left)) return false;
    while (is(TK::Slash) || is(TK::Star)) {
        Token op = tok_;
        advance();
        Node right;
        if (!parsePowerLevel(right)) return false;
        if (!binary(op, left, right)) return false;
    }
    out = std::move(left);
    return true;
}

bool Parser::parsePowerLevel(Node& out) {
    Node left;
    if (!parseFactor(left)) return false;
    while (is(TK::Power)) {
        Token op = tok_;
        advance();
        Node right;
        if (!parseFactor(right)) return false;
        if (!binary(op, left, right)) return false;
    }
    out = std::move(left);
    return true;
}

bool Parser::parseFactor(Node& out) {
    switch (tok_.kind) {
        case TK::Plus:
        case TK::Minus:
        case TK::Tilde: {
            Nest nest(*this);
            if (!nest.ok) return false;
            Token op = tok_;
            UnaryOp kind = op.kind == TK::Plus    ? UnaryOp::Plus
                           : op.kind == TK::Minus ? UnaryOp::Minus
                                                  : UnaryOp::Tilde;
            advance();
            Node operand;
            if (!parseFactor(operand)) return false;
            return unary(op, kind, operand, out);
        }
        case TK::Number: {
            out.e = newExpr(ExprKind::Number, tok_);
            out.e->number = tok_.number;
            out.h = 1;
            advance();
            return true;
        }
        case TK::LParen: {
            advance();
            if (!parseExpression(out)) return false;
            if (!is(TK::RParen)) {
                error(tok_, msg::kRightParenExpected);
                return false;
            }
            advance();
            return true;
        }
        case TK::Identifier: {
            auto it = names_.find(tok_.name);
            if (it != names_.end() && it->second.isArray) {
                Token name = tok_;
                return parseElement(out, name, it->second.slot);
            }
            if (it != names_.end()) {
                out.e = newExpr(ExprKind::Variable, tok_);
                out.e->slot = it->second.slot;
                out.h = 1;
                advance();
                return true;
            }
            return parseBodyCall(out);
        }
        case TK::Function: return parseRoutineCall(out);
        case TK::XId:
        case TK::AId:
        case TK::SId: {
            Token name = tok_;
            int slot = name.kind == TK::XId ? kArrayX : name.kind == TK::AId ? kArrayA : kArrayS;
            return parseElement(out, name, slot);
        }
        default: error(tok_, msg::kExpressionExpected); return false;
    }
}

// name [ expression ]   (tok_ is the name)
bool Parser::parseElement(Node& out, const Token& name, int slot) {
    advance();
    if (!is(TK::LBracket)) {
        error(tok_, msg::kLeftBracketExpected);
        return false;
    }
    advance();
    Node index;
    if (!parseExpression(index)) return false;
    if (!is(TK::RBracket)) {
        error(tok_, msg::kRightBracketExpected);
        return false;
    }
    advance();
    if (tooDeep(index.h + 1, name)) return false;
    out.e = newExpr(ExprKind::ArrayElement, name);
    out.e->slot = slot;
    out.e->args.push_back(std::move(index.e));
    out.h = index.h + 1;
    return true;
}

bool Parser::resolveArray(const Token& t, int& slot) const {
    switch (t.kind) {
        case TK::XId: slot = kArrayX; return true;
        case TK::AId: slot = kArrayA; return true;
        case TK::SId: slot = kArrayS; return true;
        case TK::Identifier: {
            auto it = names_.find(t.name);
            if (it == names_.end() || !it->second.isArray) return false;
            slot = it->second.slot;
            return true;
        }
        default: return false;
    }
}

// One array argument of a body call. Like the reference, any single token
// that is not a name is let through here; the call is rejected after it has
// been read (the reference would read memory outside the arrays).
bool Parser::bodyCallArgument(Expr& call, int expectedSize, const char* what, const Body& callee,
                              Token& bad, bool& hasBad) {
    if (!isArrayToken(tok_.kind)) {
        if (!hasBad) {
            bad = tok_;
            hasBad = true;
        }
        return true;
    }
    int slot = -1;
    if (!resolveArray(tok_, slot)) {
        error(tok_, msg::kOnlyArrayName,
              "the arguments of a call to body '" + callee.spelling +
                  "' must be the names of arrays (x, a, s or an array declared with 'array')");
        return false;
    }
    int size = body_->arrays[static_cast<size_t>(slot)].size;
    if (size != expectedSize) {
        error(tok_, msg::kWrongNumberOfItems,
              "body '" + callee.spelling + "' declares " + what + "[" +
                  std::to_string(expectedSize) + "] but '" + text(tok_) + "' has " +
                  std::to_string(size) + (size == 1 ? " item" : " items"));
        return false;
    }
    ExprPtr arg = newExpr(ExprKind::ArrayName, tok_);
    arg->slot = slot;
    call.args.push_back(std::move(arg));
    return true;
}

bool Parser::parseBodyCall(Node& out) {
    Token name = tok_;
    auto found = bodyIndex_.find(name.name);
    if (found == bodyIndex_.end()) {
        size_t before = errors_.size();
        error(name, msg::kUnassignedIdentifier,
              "'" + text(name) +
                  "' is neither a variable assigned above, an array of this body, nor a body "
                  "defined above this one");
        if (errors_.size() > before && errors_.back().message == msg::kUnassignedIdentifier)
            unresolved_.push_back({before, name.name, body_->name});
        return false;
    }
    const Body& callee = program_.bodies[static_cast<size_t>(found->second)];
    ExprPtr call = newExpr(ExprKind::BodyCall, name);
    call->function = found->second;

    advance();
    if (!is(TK::LParen)) {
        error(tok_, msg::kLeftParenExpected);
        return false;
    }
    Token bad;
    bool hasBad = false;
    advance();
    if (!bodyCallArgument(*call, callee.xSize(), "x", callee, bad, hasBad)) return false;
    advance();
    if (!is(TK::Comma)) {
        error(tok_, msg::kCommaExpected);
        return false;
    }
    advance();
    if (!bodyCallArgument(*call, callee.aSize(), "a", callee, bad, hasBad)) return false;
    advance();
    if (is(TK::RParen)) {
        // No s argument: the callee must have the default s size of 1.
        if (callee.sSize() != 1) {
            error(tok_, msg::kWrongNumberOfItems,
                  "body '" + callee.spelling + "' declares s[" +
                      std::to_string(callee.sSize()) + "]: pass an s array of that size");
            return false;
        }
    } else {
        if (!is(TK::Comma)) {
            error(tok_, msg::kCommaExpected);
            return false;
        }
        advance();
        if (!bodyCallArgument(*call, callee.sSize(), "s", callee, bad, hasBad)) return false;
        advance();
        if (!is(TK::RParen)) {
            error(tok_, msg::kRightParenExpected);
            return false;
        }
    }
    advance();
    if (hasBad) {
        error(bad,
              "body call arguments must be array names (x, a, s or an array declared with "
              "'array')",
              "the reference interpreter accepts this but then reads memory outside its arrays");
        return false;
    }
    out.e = std::move(call);
    out.h = 2;
    return true;
}

bool Parser::parseRoutineCall(Node& out) {
    Token name = tok_;
    const auto& ref = syntax::referenceFunctions()[static_cast<size_t>(name.function)];
    const bool builtin = name.function < syntax::kBuiltinCount;
    const int libId = builtin ? -1 : lib::findFunction(ref.name);
    std::string params(ref.params);
    if (libId >= 0) {
        params.clear();
        for (lib::ParamKind k : lib::functions()[static_cast<size_t>(libId)].params)
            params += k == lib::ParamKind::Array ? 'A' : 'R';
    }
    auto arity = [&] {
        std::string s = "'" + text(name) + "' takes " + std::to_string(params.size()) +
                         (params.size() == 1 ? " argument (" : " arguments (");
        for (size_t i = 0; i < params.size(); ++i)
            s += std::string(i ? ", " : "") + (params[i] == 'A' ? "array" : "number");
        return s + ")";
    };

    ExprPtr call = newExpr(builtin ? ExprKind::BuiltinCall : ExprKind::LibraryCall, name);
    if (builtin)
        call->builtin = kBuiltinByReferenceIndex[name.function];
    else
        call->function = libId;

    advance();
    if (!is(TK::LParen)) {
        error(tok_, msg::kLeftParenExpected);
        return false;
    }
    advance();
    int h = 1;
    for (size_t i = 0; i < params.size(); ++i) {
        if (params[i] == 'R') {
            Node arg;
            if (!parseExpression(arg)) return false;
            h = std::max(h, arg.h);
            call->args.push_back(std::move(arg.e));
        } else if (isArrayToken(tok_.kind)) {
            int slot = -1;
            if (!resolveArray(tok_, slot)) {
                error(tok_, msg::kOnlyArrayName,
                      "argument " + std::to_string(i + 1) + " of " + arity());
                return false;
            }
            ExprPtr arg = newExpr(ExprKind::ArrayName, tok_);
            arg->slot = slot;
            call->args.push_back(std::move(arg));
            advance();
        } else {
            error(tok_, msg::kArgumentError,
                  "argument " + std::to_string(i + 1) + " of " + arity() +
                      " must be an array name");
            return false;
        }
        if (i + 1 < params.size()) {
            if (!is(TK::Comma)) {
                error(tok_, msg::kCommaExpected, arity());
                return false;
            }
            advance();
        }
    }
    if (!is(TK::RParen)) {
        error(tok_, msg::kRightParenExpected, arity());
        return false;
    }
    advance();
    if (!builtin && libId < 0) {
        error(name, "library routine '" + text(name) + "' is not supported by Hypergarden");
        return false;
    }
    if (tooDeep(h + 1, name)) return false;
    out.e = std::move(call);
    out.h = h + 1;
    return true;
}

bool Parser::parseCondition(Node& out) {
    Nest nest(*this);
    if (!nest.ok) return false;
    Node left;
    if (!parseComparison(left)) return false;
    while (is(TK::And) || is(TK::Or)) {
        Token op = tok_;
        advance();
        Node right;
        if (!parseComparison(right)) return false;
        if (!binary(op, left, right)) return false;
    }
    out = std::move(left);
    return true;
}

bool Parser::parseComparison(Node& out) {
    Node left;
    if (!parseBoolOperand(left)) return false;
    while (is(TK::NotEqual) || is(TK::Less) || is(TK::LessEqual) || is(TK::Greater) ||
           is(TK::GreaterEqual) || is(TK::Assign)) {
        Token op = tok_;
        advance();
        Node right;
        if (!parseBoolOperand(right)) return false;
        if (!binary(op, left, right)) return false;
    }
    out = std::move(left);
    return true;
}

bool Parser::parseBoolOperand(Node& out) {
    if (is(TK::Not)) {
        Nest nest(*this);
        if (!nest.ok) return false;
        Token op = tok_;
        advance();
        Node operand;
        if (!parseBoolOperand(operand)) return false;
        return unary(op, UnaryOp::Not, operand, out);
    }
    if (is(TK::LParen)) {
        advance();
        if (!parseCondition(out)) return false;
        if (!is(TK::RParen)) {
            error(tok_, msg::kRightParenExpected);
            return false;
        }
        advance();
        return true;
    }
    return parseExpression(out);
}

// ---------------------------------------------------------------------------
// Statements

int Parser::addVariable(const Token& t) {
    countNodes(1, t);
    int slot = static_cast<int>(body_->variables.size());
    VariableInfo v;
    v.name = t.name;
    v.spelling = text(t);
    v.loc = t.loc;
    body_->variables.push_back(std::move(v));
    names_[t.name] = NameInfo{false, slot};
    return slot;
}

bool Parser::parseStatements(std::vector<Stmt>& out) {
    bool anyError = false;
    for (;;) {
        bool failed = false;
        bool stop = false;
        switch (tok_.kind) {
            case TK::If: failed = !parseIf(out); break;
            case TK::While: failed = !parseWhile(out); break;
            case TK::SId:
            case TK::Identifier: {
                int slot = kArrayS;
                bool isArray = true;
                if (is(TK::Identifier)) {
                    if (tok_.name == body_->name) {
                        stop = true;  // the final body-name assignment
                        break;
                    }
                    auto it = names_.find(tok_.name);
                    if (it == names_.end()) {
                        // Variables exist from their first assignment on,
                        // including in its own right-hand side.
                        slot = addVariable(tok_);
                        isArray = false;
                    } else {
                        slot = it->second.slot;
                        isArray = it->second.isArray;
                    }
                }
                if (!isArray) {
                    failed = !parseAssign(out, slot);
                    break;
                }
                Token name = tok_;
                advance();
                if (is(TK::LBracket)) {
                    advance();
                    failed = !parseElementAssign(out, name, slot);
                } else if (is(TK::Assign)) {
                    advance();
                    failed = !parseArrayLiteral(out, name, slot);
                } else {
                    error(tok_, msg::kLeftBracketOrAssign);
                    failed = true;
                }
                break;
            }
            default: stop = true; break;
        }
        anyError = anyError || failed;
        if (stop) break;
        if (failed) {
            skipToSemicolon();
            if (!is(TK::Semicolon)) break;
            advance();
        }
    }
    return anyError;
}

bool Parser::parseIf(std::vector<Stmt>& out) {
    Nest nest(*this);
    if (!nest.ok) return false;
    Stmt s;
    s.kind = StmtKind::If;
    s.loc = tok_.loc;
    countNodes(1, tok_);
    advance();
    Node condition;
    if (!parseCondition(condition)) return false;
    if (!is(TK::Then)) {
        error(tok_, msg::kThenExpected);
        return false;
    }
    advance();
    if (parseStatements(s.thenBody)) return false;
    if (is(TK::Else)) {
        advance();
        if (parseStatements(s.elseBody)) return false;
        if (!is(TK::EndIf)) {
            error(tok_, msg::kEndIfExpected,
                  is(TK::Identifier) && tok_.name == body_->name
                      ? "the assignment to the body name must be the last statement of the "
                        "body, outside if and while"
                      : std::string());
            return false;
        }
    } else if (!is(TK::EndIf)) {
        error(tok_, msg::kElseEndIfExpected,
              is(TK::Identifier) && tok_.name == body_->name
                  ? "the assignment to the body name must be the last statement of the body, "
                    "outside if and while"
                  : std::string());
        return false;
    }
    advance();
    if (!is(TK::Semicolon)) {
        error(tok_, msg::kSemicolonExpected);
        return false;
    }
    advance();
    s.condition = std::move(condition.e);
    out.push_back(std::move(s));
    return true;
}

bool Parser::parseWhile(std::vector<Stmt>& out) {
    Nest nest(*this);
    if (!nest.ok) return false;
    Stmt s;
    s.kind = StmtKind::While;
    s.loc = tok_.loc;
    countNodes(1, tok_);
    advance();
    Node condition;
    if (!parseCondition(condition)) return false;
    if (!is(TK::Loop)) {
        error(tok_, msg::kLoopExpected);
        return false;
    }
    advance();
    if (parseStatements(s.thenBody)) return false;
    if (!is(TK::EndLoop)) {
        error(tok_, msg::kEndLoopExpected,
              is(TK::Identifier) && tok_.name == body_->name
                  ? "the assignment to the body name must be the last statement of the body, "
                    "outside if and while"
                  : std::string());
        return false;
    }
    advance();
    if (!is(TK::Semicolon)) {
        error(tok_, msg::kSemicolonExpected);
        return false;
    }
    advance();
    s.condition = std::move(condition.e);
    out.push_back(std::move(s));
    return true;
}

// name = expression ;   (tok_ is the name)
bool Parser::parseAssign(std::vector<Stmt>& out, int slot) {
    Stmt s;
    s.kind = StmtKind::Assign;
    s.loc = tok_.loc;
    s.slot = slot;
    countNodes(1, tok_);
    advance();
    if (!is(TK::Assign)) {
        error(tok_, msg::kAssignMarkExpected);
        return false;
    }
    advance();
    Node value;
    if (!parseExpression(value)) return false;
    if (!is(TK::Semicolon)) {
        error(tok_, msg::kSemicolonExpected);
        return false;
    }
    advance();
    s.value = std::move(value.e);
    out.push_back(std::move(s));
    return true;
}

// name [ index ] = expression ;   (tok_ follows the '[')
bool Parser::parseElementAssign(std::vector<Stmt>& out, const Token& name, int slot) {
    Stmt s;
    s.kind = StmtKind::AssignElement;
    s.loc = name.loc;
    s.slot = slot;
    countNodes(1, name);
    Node index;
    if (!parseExpression(index)) return false;
    if (!is(TK::RBracket)) {
        error(tok_, msg::kRightBracketExpected);
        return false;
    }
    advance();
    if (!is(TK::Assign)) {
        error(tok_, msg::kAssignMarkExpected);
        return false;
    }
    advance();
    Node value;
    bool valueOk = parseExpression(value);
    // As the reference: for a local array an error in the value is followed
    // by the check for the semicolon; for s[] it ends the statement.
    if (!valueOk && slot == kArrayS) return false;
    if (!is(TK::Semicolon)) {
        error(tok_, msg::kSemicolonExpected);
        return false;
    }
    advance();
    if (!valueOk) return false;
    s.index = std::move(index.e);
    s.value = std::move(value.e);
    out.push_back(std::move(s));
    return true;
}

// name = [ n, n, ... ] ;   (tok_ follows the '=')
bool Parser::parseArrayLiteral(std::vector<Stmt>& out, const Token& name, int slot) {
    const int amount = body_->arrays[static_cast<size_t>(slot)].size;
    if (amount < 1) {
        // The reference would write past the end of the array.
        error(name, "'" + text(name) + "' has no items and cannot be assigned a literal");
        return false;
    }
    if (!is(TK::LBracket)) {
        error(tok_, msg::kLeftBracketExpected);
        return false;
    }
    advance();
    std::vector<double> values;
    auto item = [&]() {
        double sign = 1.0;
        if (is(TK::Minus)) {
            sign = -1.0;
            advance();
        } else if (is(TK::Plus)) {
            advance();
        }
        if (!is(TK::Number)) {
            error(tok_, msg::kRealNumberExpected,
                  "array literals hold numbers only, each with at most one sign");
            return false;
        }
        values.push_back(tok_.number * sign);
        advance();
        return true;
    };
    if (!item()) return false;
    for (int i = 0; i < amount - 1; ++i) {
        if (!is(TK::Comma)) {
            error(tok_, msg::kCommaExpected,
                  "'" + text(name) + "' holds " + std::to_string(amount) +
                      " items; the literal must list that many");
            return false;
        }
        advance();
        if (!item()) return false;
    }
    if (!is(TK::RBracket)) {
        error(tok_, msg::kRightBracketExpected,
              "'" + text(name) + "' holds " + std::to_string(amount) +
                  (amount == 1 ? " item" : " items") + "; the literal must list that many");
        return false;
    }
    advance();
    if (!is(TK::Semicolon)) {
        error(tok_, msg::kSemicolonExpected);
        return false;
    }
    advance();
    countNodes(1 + values.size() / 8, name);  // numbers are small: 8 count as one node
    Stmt s;
    s.kind = StmtKind::AssignArray;
    s.loc = name.loc;
    s.slot = slot;
    s.literal = std::move(values);
    out.push_back(std::move(s));
    return true;
}

// array name[size], name[size], ... ;   (tok_ is 'array')
void Parser::parseArrayDecl() {
    do {
        advance();
        if (!is(TK::Identifier)) {
            error(tok_, msg::kIdentifierExpected,
                  is(TK::XId) || is(TK::AId) || is(TK::SId) || is(TK::Function)
                      ? "'" + text(tok_) + "' is a reserved name"
                      : std::string());
            skipToSemicolon();
            break;
        }
        Token name = tok_;
        advance();
        if (!is(TK::LBracket)) {
            error(tok_, msg::kLeftBracketExpected);
            skipToSemicolon();
            break;
        }
        advance();
        if (!is(TK::Number)) {
            error(tok_, msg::kRealNumberExpected);
            skipToSemicolon();
            break;
        }
        Token sizeToken = tok_;
        double size = hfRound(tok_.number);
        // The reference converts the size to int: on x86 values from 2^31
        // (and NaN) become INT_MIN and are refused as below 1.
        if (!(size >= 1.0) || size >= 2147483648.0) {
            error(tok_, msg::kArraySizeGreaterZero);
            skipToSemicolon();
            break;
        }
        if (size > Limits::kMaxArraySize) {
            error(tok_, "array too large: " + text(tok_) + " items (the limit is " +
                            std::to_string(Limits::kMaxArraySize) + ")");
            skipToSemicolon();
            break;
        }
        advance();
        if (!is(TK::RBracket)) {
            error(tok_, msg::kRightBracketExpected);
            skipToSemicolon();
            break;
        }
        const int n = static_cast<int>(size);
        bodyArrayItems_ += n;
        if (bodyArrayItems_ > Limits::kMaxBodyArrayItems)
            error(sizeToken, "arrays too large: the arrays of body '" + body_->spelling +
                                 "' hold more than " +
                                 std::to_string(Limits::kMaxBodyArrayItems) + " items");
        if (names_.find(name.name) == names_.end()) {
            // A repeated name keeps its first declaration, as in the reference.
            countNodes(1, name);
            ArrayInfo info;
            info.name = name.name;
            info.spelling = text(name);
            info.size = n;
            info.loc = name.loc;
            names_[name.name] = NameInfo{true, static_cast<int>(body_->arrays.size())};
            body_->arrays.push_back(std::move(info));
        }
        advance();
    } while (is(TK::Comma));
    if (!is(TK::Semicolon)) {
        error(tok_, msg::kSemicolonExpected);
        skipToSemicolon();
    }
    advance();
}

// [ size ]  of x, a or s in the parameter list (tok_ follows the name)
bool Parser::parseParamSize(int& size) {
    advance();
    if (!is(TK::LBracket)) {
        error(tok_, msg::kLeftBracketExpected);
        return false;
    }
    advance();
    if (!is(TK::Number)) {
        error(tok_, msg::kRealNumberExpected);
        return false;
    }
    double r = hfRound(tok_.number);
    if (!(r <= Limits::kMaxArraySize)) {
        error(tok_, "array too large: " + text(tok_) + " items (the limit is " +
                        std::to_string(Limits::kMaxArraySize) + ")");
        return false;
    }
    size = static_cast<int>(r);
    bodyArrayItems_ += size;
    advance();
    if (!is(TK::RBracket)) {
        error(tok_, msg::kRightBracketExpected);
        return false;
    }
    return true;
}

// ( x[n], a[n] [, s[n]] ) {   (tok_ is the body name)
bool Parser::parseParams(Body& b) {
    auto addParam = [&](const char* name, const Token& t, int size) {
        ArrayInfo info;
        info.name = name;
        info.spelling = t.kind == TK::End ? std::string(name) : text(t);
        info.size = size;
        info.loc = t.loc;
        b.arrays.push_back(std::move(info));
    };
    advance();
    if (!is(TK::LParen)) {
        error(tok_, msg::kLeftParenExpected);
        return false;
    }
    advance();
    if (!is(TK::XId)) {
        error(tok_, msg::kXExpected);
        return false;
    }
    Token xName = tok_;
    int xSize = 0;
    if (!parseParamSize(xSize)) return false;
    advance();
    if (!is(TK::Comma)) {
        error(tok_, msg::kCommaExpected);
        return false;
    }
    advance();
    if (!is(TK::AId)) {
        error(tok_, msg::kAExpected);
        return false;
    }
    Token aName = tok_;
    int aSize = 0;
    if (!parseParamSize(aSize)) return false;
    addParam("x", xName, xSize);
    addParam("a", aName, aSize);
    advance();
    if (is(TK::RParen)) {
        Token none;  // s is not declared: it has one item
        none.loc = SourceLoc{0, 0};
        addParam("s", none, 1);
        b.declaresS = false;
    } else {
        if (!is(TK::Comma)) {
            error(tok_, msg::kCommaExpected);
            return false;
        }
        advance();
        if (!is(TK::SId)) {
            error(tok_, msg::kSExpected);
            return false;
        }
        Token sName = tok_;
        int sSize = 0;
        if (!parseParamSize(sSize)) return false;
        addParam("s", sName, sSize);
        b.declaresS = true;
        advance();
        if (!is(TK::RParen)) {
            error(tok_, msg::kRightParenExpected);
            return false;
        }
    }
    advance();
    if (!is(TK::LBrace)) {
        error(tok_, msg::kLeftBraceExpected);
        return false;
    }
    return true;
}

// { declarations statements name = expression ; }   (tok_ is '{')
// Returns true when the body was read up to its closing brace.
bool Parser::parseBodyDef(Body& b) {
    advance();
    while (is(TK::Array)) parseArrayDecl();
    parseStatements(b.statements);
    if (!is(TK::Identifier) || tok_.name != b.name) {
        std::string note;
        if (is(TK::XId) || is(TK::AId))
            note = "the items of x[] and a[] cannot be assigned; copy them into a local array";
        else if (is(TK::Array))
            note = "array declarations must come before the first statement";
        else if (is(TK::Function))
            note = "'" + text(tok_) + "' is a reserved routine name";
        else if (is(TK::RBrace) || is(TK::End))
            note = "a body ends with the assignment '" + b.spelling + " = expression;'";
        error(tok_, msg::kBodyNameExpected, note);
        return false;
    }
    Token name = tok_;
    advance();
    if (!is(TK::Assign)) {
        error(tok_, msg::kAssignMarkExpected);
        return false;
    }
    advance();
    Node value;
    if (!parseExpression(value)) return false;
    if (!is(TK::Semicolon)) {
        error(tok_, msg::kSemicolonExpected);
        return false;
    }
    advance();
    if (!is(TK::RBrace)) {
        error(tok_, msg::kRightBraceExpected,
              "the assignment to '" + b.spelling + "' must be the last statement of the body");
        advance();
        return false;
    }
    advance();
    b.result = std::move(value.e);
    b.resultLoc = name.loc;
    return true;
}

// Notes for "Unassigned identificator" errors that name the body itself or
// a body defined further down (found by its header "name ( x [").
void Parser::explainUnresolved() {
    if (unresolved_.empty()) return;
    std::unordered_map<std::string, std::pair<SourceLoc, std::string>> headers;
    syntax::Lexer lexer(lex_.source());
    Token window[4];
    for (size_t n = 0;; ++n) {
        window[0] = std::move(window[1]);
        window[1] = std::move(window[2]);
        window[2] = std::move(window[3]);
        window[3] = lexer.next();
        if (window[3].kind == TK::End) break;
        if (n >= 3 && window[0].kind == TK::Identifier && window[1].kind == TK::LParen &&
            window[2].kind == TK::XId && window[3].kind == TK::LBracket)
            headers.emplace(window[0].name, std::make_pair(window[0].loc, text(window[0])));
    }
    for (const Unresolved& u : unresolved_) {
        if (u.error >= errors_.size()) continue;
        if (u.name == u.caller) {
            errors_[u.error].note = "a body cannot call itself";
            continue;
        }
        auto it = headers.find(u.name);
        if (it != headers.end() && it->second.first.line >= errors_[u.error].loc.line)
            errors_[u.error].note = "body '" + it->second.second + "' is defined below (line " +
                                    std::to_string(it->second.first.line) +
                                    "); a body can only call bodies defined above it";
    }
}

ParseResult Parser::run() {
    advance();
    while (!is(TK::End)) {
        if (!is(TK::Identifier)) {
            error(tok_, msg::kBodyNameExpected,
                  is(TK::Function) || is(TK::XId) || is(TK::AId) || is(TK::SId)
                      ? "'" + text(tok_) + "' is a reserved name"
                      : std::string());
            break;
        }
        if (bodyIndex_.count(tok_.name)) {
            error(tok_, msg::kBodyNameNotUnique);
            break;
        }
        countNodes(8, tok_);
        Body b;
        b.name = tok_.name;
        b.spelling = text(tok_);
        b.loc = tok_.loc;
        names_.clear();
        bodyArrayItems_ = 0;
        body_ = &b;
        if (!parseParams(b)) {
            body_ = nullptr;
            break;
        }
        bool closed = parseBodyDef(b);
        body_ = nullptr;
        // Registered even when it has errors, so that later bodies that
        // call it do not report spurious errors (the parse fails anyway).
        bodyIndex_.emplace(b.name, static_cast<int>(program_.bodies.size()));
        program_.bodies.push_back(std::move(b));
        // The reference stops after the first body with an error; we go on
        // to report errors in later bodies when this one ended cleanly.
        if (!closed) break;
    }
    if (errors_.empty() && program_.bodies.empty())
        error(tok_, "the program has no body", "a program is one or more bodies such as "
                                               "'my_model(x[3], a[1]) { my_model = ...; }'");

    explainUnresolved();

    ParseResult result;
    result.errors = std::move(errors_);
    if (result.errors.empty()) result.program = std::move(program_);
    return result;
}

}  // namespace

ParseResult parseProgram(std::string_view source, const std::string& fileName) {
    if (source.size() > ParseLimits::kMaxSourceBytes) {
        ParseResult r;
        Diagnostic d;
        d.file = fileName;
        d.message = "source too large: " + std::to_string(source.size()) +
                    " bytes (the limit is " + std::to_string(ParseLimits::kMaxSourceBytes >> 20) +
                    " MiB)";
        r.errors.push_back(std::move(d));
        return r;
    }
    Parser parser(source, fileName);
    ParseResult result = parser.run();
    if (result.program) result.program->file = fileName;
    return result;
}

ParseResult parseFile(const std::string& path) {
    auto fail = [&](std::string message) {
        ParseResult r;
        Diagnostic d;
        d.file = path;
        d.message = std::move(message);
        r.errors.push_back(std::move(d));
        return r;
    };
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) return fail("cannot read file: it is a directory");
    std::FILE* f = std::fopen(path.c_str(), "rb");
    if (!f) return fail(std::string("cannot open file: ") + std::strerror(errno));
    std::string data;
    char buffer[1 << 16];
    bool tooLarge = false;
    bool readError = false;
    for (;;) {
        size_t n = std::fread(buffer, 1, sizeof buffer, f);
        data.append(buffer, n);
        if (data.size() > ParseLimits::kMaxSourceBytes) {
            tooLarge = true;
            break;
        }
        if (n < sizeof buffer) {
            readError = std::ferror(f) != 0;
            break;
        }
    }
    int savedErrno = errno;
    std::fclose(f);
    if (tooLarge)
        return fail("file too large: more than " +
                    std::to_string(ParseLimits::kMaxSourceBytes >> 20) + " MiB");
    if (readError) return fail(std::string("cannot read file: ") + std::strerror(savedErrno));
    return parseProgram(data, path);
}

}  // namespace hg::frep
