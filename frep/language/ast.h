// The parsed form of a HyperFun program: bodies of statements over scalar
// variables and fixed-size arrays. Every node keeps its source location so
// that diagnostics and runtime errors can point at the text.
//
// Names are resolved by the parser: variables and arrays become slot
// indices into their body's tables, library and built-in calls become ids,
// body calls become indices of earlier bodies. Evaluators never look at
// strings.
#pragma once

#include <memory>
#include <string>
#include <vector>

namespace hg::frep {

struct SourceLoc {
    int line = 0;    // from 1
    int column = 0;  // from 1; a tab counts as one column
};

// Built-in (non-library) functions of the language.
enum class Builtin {
    Sqrt, Exp, Log, Logd, Sin, Cos, Tan, Asin, Acos, Atan, Atan2, Abs,
    Sinh, Cosh, Tanh, Sign, Mod, Max, Min, Ceil, Floor, Int, Frac,
};

enum class UnaryOp { Plus, Minus, Tilde, Not };

// Arithmetic, set and condition operators. Set operators use alpha = 0.
// Comparisons and And/Or give 0 or 1 and only appear in conditions.
enum class BinaryOp {
    Add, Sub, Mul, Div, Pow,
    Union,         // |
    Intersection,  // & and @
    Difference,    // '\'
    Equal, NotEqual, Less, LessEqual, Greater, GreaterEqual,
    And, Or,
};

enum class ExprKind {
    Number,        // number
    Variable,      // slot: scalar variable of the body
    ArrayElement,  // slot: array of the body; args[0] is the index expression
    ArrayName,     // slot: a whole array passed to a library routine or body
    Unary,         // unaryOp; args[0]
    Binary,        // binaryOp; args[0] op args[1]
    BuiltinCall,   // builtin; args
    LibraryCall,   // function: library id (frep/kernels/library/library.h); args
    BodyCall,      // function: index of an earlier body; args are ArrayName
};

struct Expr {
    ExprKind kind = ExprKind::Number;
    SourceLoc loc;
    double number = 0.0;
    int slot = -1;
    int function = -1;
    Builtin builtin = Builtin::Sqrt;
    UnaryOp unaryOp = UnaryOp::Plus;
    BinaryOp binaryOp = BinaryOp::Add;
    std::string spelling;  // as written, for the writer and messages
    std::vector<std::unique_ptr<Expr>> args;
};
using ExprPtr = std::unique_ptr<Expr>;

enum class StmtKind {
    Assign,         // slot (scalar variable) = value
    AssignElement,  // slot (array) [index] = value
    AssignArray,    // slot (array) = [literal...]
    If,             // if condition then thenBody [else elseBody] endif
    While,          // while condition loop thenBody endloop
};

struct Stmt {
    StmtKind kind = StmtKind::Assign;
    SourceLoc loc;
    int slot = -1;
    ExprPtr index;
    ExprPtr value;
    std::vector<double> literal;
    ExprPtr condition;
    std::vector<Stmt> thenBody;
    std::vector<Stmt> elseBody;
};

// Array slots 0, 1 and 2 are always x, a and s; locals follow.
constexpr int kArrayX = 0;
constexpr int kArrayA = 1;
constexpr int kArrayS = 2;

struct ArrayInfo {
    std::string name;  // lower case
    std::string spelling;
    int size = 0;
    SourceLoc loc;
};

struct VariableInfo {
    std::string name;  // lower case
    std::string spelling;
    SourceLoc loc;     // first assignment
};

struct Body {
    std::string name;  // lower case
    std::string spelling;
    SourceLoc loc;
    bool declaresS = false;           // s[] in the parameter list
    std::vector<ArrayInfo> arrays;    // x, a, s, then locals; s has size 1 when not declared
    std::vector<VariableInfo> variables;
    std::vector<Stmt> statements;     // everything before the body-name assignment
    ExprPtr result;                   // the final `name = expr;`
    SourceLoc resultLoc;

    int xSize() const { return arrays[kArrayX].size; }
    int aSize() const { return arrays[kArrayA].size; }
    int sSize() const { return arrays[kArrayS].size; }
};

struct Program {
    std::string file;  // as given to the parser, for messages
    std::vector<Body> bodies;

    // Index of the body with that (case-insensitive) name, or -1.
    int findBody(const std::string& name) const;
    // The body the conformance harness evaluates: `my_model`, else the first.
    int defaultBody() const;
};

}  // namespace hg::frep
