#include "frep/language/lexer.h"

#include <cmath>
#include <cstdio>
#include <unordered_map>

namespace hg::frep::syntax {

namespace {

bool isDigit(char c) { return c >= '0' && c <= '9'; }
bool isAlpha(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }
bool isNameChar(char c) { return isDigit(c) || isAlpha(c) || c == '_'; }
char toLower(char c) { return (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c; }
int digitValue(char c) { return c - '0'; }

struct Reserved {
    TokenKind kind;
    int function;
};

const std::unordered_map<std::string_view, Reserved>& reservedNames() {
    static const std::unordered_map<std::string_view, Reserved> table = [] {
        std::unordered_map<std::string_view, Reserved> t = {
            {"a", {TokenKind::AId, -1}},         {"s", {TokenKind::SId, -1}},
            {"x", {TokenKind::XId, -1}},         {"and", {TokenKind::And, -1}},
            {"or", {TokenKind::Or, -1}},         {"not", {TokenKind::Not, -1}},
            {"xor", {TokenKind::Xor, -1}},       {"array", {TokenKind::Array, -1}},
            {"if", {TokenKind::If, -1}},         {"then", {TokenKind::Then, -1}},
            {"else", {TokenKind::Else, -1}},     {"endif", {TokenKind::EndIf, -1}},
            {"while", {TokenKind::While, -1}},   {"loop", {TokenKind::Loop, -1}},
            {"endloop", {TokenKind::EndLoop, -1}},
        };
        const auto& functions = referenceFunctions();
        for (size_t i = 0; i < functions.size(); ++i)
            t.emplace(functions[i].name, Reserved{TokenKind::Function, static_cast<int>(i)});
        return t;
    }();
    return table;
}

}  // namespace

const std::vector<ReferenceFunction>& referenceFunctions() {
    // Names (lower-cased) and parameter kinds of the reference's
    // functions_info table (int_global.c), in its order.
    static const std::vector<ReferenceFunction> table = {
        {"sqrt", "R"}, {"exp", "R"}, {"log", "R"}, {"logd", "R"}, {"sin", "R"},
        {"cos", "R"}, {"tan", "R"}, {"asin", "R"}, {"acos", "R"}, {"atan", "R"},
        {"abs", "R"}, {"sinh", "R"}, {"cosh", "R"}, {"tanh", "R"}, {"sign", "R"},
        {"mod", "RR"}, {"max", "RR"}, {"min", "RR"}, {"atan2", "RR"},
        {"ceil", "R"}, {"floor", "R"}, {"int", "R"}, {"frac", "R"},
        // library routines
        {"hfsphere", "AAR"}, {"hfellipsoid", "AARRR"},
        {"hftorusz", "AARR"}, {"hftorusx", "AARR"}, {"hftorusy", "AARR"},
        {"hfellcylx", "AARR"}, {"hfellcyly", "AARR"}, {"hfellcylz", "AARR"},
        {"hfcylinderx", "AAR"}, {"hfcylindery", "AAR"}, {"hfcylinderz", "AAR"},
        {"hfblock", "AARRR"}, {"hfblobby", "AAAAAAR"}, {"hfmetaball", "AAAAAAR"},
        {"hfsoft", "AAAAAR"}, {"hfscale3d", "ARRR"}, {"hfshift3d", "ARRR"},
        {"hfrotate3dz", "AR"}, {"hfrotate3dy", "AR"}, {"hfrotate3dx", "AR"},
        {"hfblenduni", "RRRRR"}, {"hfblendint", "RRRRR"},
        {"hftwistz", "ARRRR"}, {"hftwisty", "ARRRR"}, {"hftwistx", "ARRRR"},
        {"hfstretch3d", "AARRR"},
        {"hftaperz", "ARRRR"}, {"hftapery", "ARRRR"}, {"hftaperx", "ARRRR"},
        {"hfconvpoint", "AAAR"}, {"hfconvline", "AAAAR"}, {"hfconvarc", "AAAAAAAR"},
        {"hfconvtriangle", "AAAR"}, {"hfbeziervolume", "ARRRAA"},
        {"hfconvliner", "AAAR"}, {"hfconvcurve", "AAAR"}, {"hfconvmesh", "AAAAR"},
        {"hfnoiseg", "ARRR"}, {"hfsuperell", "AARRRRR"},
        {"hfconex", "AAR"}, {"hfconey", "AAR"}, {"hfconez", "AAR"},
        {"hfellconex", "AARR"}, {"hfellconey", "AARR"}, {"hfellconez", "AARR"},
        {"hfspacemapcubic", "AAAA"}, {"hfspacemapexp", "AAAA"},
        // attribute routines
        {"hfa_wave", "RRRR"}, {"hfa_checkerboard", "AAAAAA"}, {"hfa_union", "RRAAAR"},
        {"hfa_crackles", "AARAA"}, {"hfa_circles", "AAAA"}, {"hfa_noiseg", "ARR"},
        {"hfa_noisep", "A"}, {"hfa_turbulence", "AR"}, {"hfa_setcolor", "RARRR"},
        {"hfa_setattributes", "RAA"}, {"hfa_lerp", "AAARRR"}, {"hfa_cerp", "AAARRR"},
        {"hfa_clamp", "RRR"}, {"hfa_floor", "R"}, {"hfa_pulse", "RRR"},
        {"hfa_lookuptable", "RAAA"}, {"hfa_smoothlookuptable", "RAAA"},
        {"hfa_step", "RR"}, {"hfa_smoothstep", "RRRRRR"}, {"hfa_modulo", "RR"},
        {"hfa_spline", "AARRR"}, {"hfa_rgbtohsv", "AA"}, {"hfa_hsvtorgb", "AA"},
        // distance primitives and operations
        {"hfdconex", "AAR"}, {"hfdconey", "AAR"}, {"hfdconez", "AAR"},
        {"hfdcylinder", "AAAR"}, {"hfdellipsoid", "AARRR"},
        {"hfdtorusx", "AARR"}, {"hfdtorusy", "AARR"}, {"hfdtorusz", "AARR"},
        {"hfduni", "RRRR"}, {"hfdint", "RRRR"}, {"hfdsub", "RRRR"},
        {"hfdblenduni", "RRR"}, {"hfdblendint", "RRR"},
        {"hfsawtooth", "RRRR"},
    };
    return table;
}

Lexer::Lexer(std::string_view source) : src_(source) {
    // The reference works on a C string: a NUL byte ends the program.
    size_t nul = src_.find('\0');
    if (nul != std::string_view::npos) src_ = src_.substr(0, nul);
}

void Lexer::advance(size_t n) {
    pos_ += n;
    column_ += static_cast<int>(n);
}

Token Lexer::next() {
    for (;;) {
        Token t = scan();
        if (t.kind != TokenKind::Comment) return t;
    }
}

Token Lexer::scan() {
    // White space: blank, tab, new line; nothing else.
    for (;;) {
        char c = at(pos_);
        if (c == '\n') {
            ++pos_;
            ++line_;
            column_ = 1;
        } else if (c == ' ' || c == '\t') {
            advance();
        } else {
            break;
        }
    }

    Token t;
    t.loc = SourceLoc{line_, column_};
    t.offset = pos_;
    auto finish = [&](TokenKind kind, size_t n) {
        advance(n);
        t.kind = kind;
        t.length = pos_ - t.offset;
        return t;
    };

    const char c = at(pos_);
    if (pos_ >= src_.size()) {
        t.kind = TokenKind::End;
        return t;
    }
    switch (c) {
        case '^': return finish(TokenKind::Power, 1);
        case '+': return finish(TokenKind::Plus, 1);
        case '-':
            if (at(pos_ + 1) == '-') {
                // Comment to the end of the line, at most 256 characters.
                size_t count = 0;
                size_t i = pos_ + 2;
                while (at(i) != '\n' && at(i) != '\0' && count < kMaxLexemLength) {
                    ++i;
                    ++count;
                }
                if (at(i) != '\n' && at(i) != '\0') {
                    t.problem = LexProblem::LongComment;
                    return finish(TokenKind::Illegal, i - pos_);
                }
                return finish(TokenKind::Comment, i - pos_);
            }
            return finish(TokenKind::Minus, 1);
        case '~': return finish(TokenKind::Tilde, 1);
        case '/':
            if (at(pos_ + 1) == '=') return finish(TokenKind::NotEqual, 2);
            return finish(TokenKind::Slash, 1);
        case '*': return finish(TokenKind::Star, 1);
        case '&': return finish(TokenKind::Ampersand, 1);
        case '|': return finish(TokenKind::Union, 1);
        case '\\': return finish(TokenKind::Backslash, 1);
        case '@': return finish(TokenKind::At, 1);
        case ',': return finish(TokenKind::Comma, 1);
        case ';': return finish(TokenKind::Semicolon, 1);
        case '=': return finish(TokenKind::Assign, 1);
        case '(': return finish(TokenKind::LParen, 1);
        case ')': return finish(TokenKind::RParen, 1);
        case '[': return finish(TokenKind::LBracket, 1);
        case ']': return finish(TokenKind::RBracket, 1);
        case '{': return finish(TokenKind::LBrace, 1);
        case '}': return finish(TokenKind::RBrace, 1);
        case '<':
            if (at(pos_ + 1) == '=') return finish(TokenKind::LessEqual, 2);
            return finish(TokenKind::Less, 1);
        case '>':
            if (at(pos_ + 1) == '=') return finish(TokenKind::GreaterEqual, 2);
            return finish(TokenKind::Greater, 1);
        case '"': {
            size_t count = 0;
            size_t i = pos_ + 1;
            while (at(i) != '"' && at(i) != '\0' && at(i) != '\n' && count < kMaxLexemLength) {
                ++i;
                ++count;
            }
            if (at(i) != '"' || count >= kMaxLexemLength) {
                t.problem = LexProblem::UnterminatedString;
                return finish(TokenKind::Illegal, i - pos_);
            }
            t.name.assign(src_.substr(pos_ + 1, count));
            return finish(TokenKind::String, i + 1 - pos_);
        }
        default: break;
    }

    if (isDigit(c) || c == '.') {
        // Integer[.Integer][(E|e)[+|-]Integer], or .Integer[...]
        size_t i = pos_;
        double value = 0.0;
        bool numeric = false;
        LexProblem problem = LexProblem::None;
        if (c != '.') {
            numeric = true;
            value = digitValue(c);
            ++i;
            if (c == '0' && isDigit(at(i))) problem = LexProblem::LeadingZero;
        }
        if (problem == LexProblem::None) {
            while (isDigit(at(i))) {
                value = value * 10.0 + digitValue(at(i));
                ++i;
            }
            if (at(i) == '.') {
                ++i;
                if (isDigit(at(i))) {
                    double scale = 10.0;
                    while (isDigit(at(i))) {
                        value = value + digitValue(at(i)) / scale;
                        scale = scale * 10.0;
                        ++i;
                    }
                } else if (!numeric) {
                    problem = LexProblem::LoneDot;
                }
            }
            if (problem == LexProblem::None && (at(i) == 'E' || at(i) == 'e')) {
                ++i;
                double exponent = 1.0;
                if (at(i) == '-') {
                    ++i;
                    exponent = -1.0;
                } else if (at(i) == '+') {
                    ++i;
                }
                if (at(i) == '0' || !isDigit(at(i))) {
                    problem = LexProblem::BadExponent;
                } else {
                    // As the reference: the sign applies to the first digit
                    // only (1e-12 scales by 10^-8).
                    exponent = exponent * digitValue(at(i));
                    ++i;
                    while (isDigit(at(i))) {
                        exponent = exponent * 10.0 + digitValue(at(i));
                        ++i;
                    }
                    value = value * std::exp(exponent * std::log(10.0));
                }
            }
        }
        t.problem = problem;
        t.number = value;
        return finish(problem == LexProblem::None ? TokenKind::Number : TokenKind::Illegal, i - pos_);
    }

    if (isAlpha(c)) {
        size_t i = pos_;
        while (isNameChar(at(i)) && i - pos_ < kMaxLexemLength) ++i;
        if (isNameChar(at(i))) {
            t.problem = LexProblem::LongIdentifier;
            return finish(TokenKind::Illegal, i - pos_);
        }
        t.name.reserve(i - pos_);
        for (size_t k = pos_; k < i; ++k) t.name.push_back(toLower(src_[k]));
        const auto& reserved = reservedNames();
        auto it = reserved.find(t.name);
        if (it != reserved.end()) {
            t.function = it->second.function;
            return finish(it->second.kind, i - pos_);
        }
        return finish(TokenKind::Identifier, i - pos_);
    }

    t.problem = c == '\r' ? LexProblem::CarriageReturn : LexProblem::UnknownCharacter;
    return finish(TokenKind::Illegal, 1);
}

std::string describe(const Token& token, std::string_view source) {
    auto text = [&] {
        std::string s(source.substr(token.offset, token.length));
        return s;
    };
    switch (token.problem) {
        case LexProblem::None: return {};
        case LexProblem::LeadingZero:
            return "malformed number: a number may not start with 0 followed by another digit";
        case LexProblem::BadExponent:
            return "malformed number '" + text() +
                   "': the exponent needs digits and may not start with 0";
        case LexProblem::LoneDot: return "a '.' without digits is not a number";
        case LexProblem::CarriageReturn:
            return "carriage return (CR) is not white space in HyperFun; save the file with "
                   "LF line endings";
        case LexProblem::UnknownCharacter: {
            unsigned char c = static_cast<unsigned char>(source[token.offset]);
            char buf[64];
            if (c >= 0x21 && c < 0x7f)
                std::snprintf(buf, sizeof buf, "unknown character '%c'", c);
            else
                std::snprintf(buf, sizeof buf, "unknown character (byte 0x%02X)", c);
            return buf;
        }
        case LexProblem::LongComment:
            return "comment longer than 256 characters: the reference interpreter rejects it";
        case LexProblem::LongIdentifier: return "name longer than 256 characters";
        case LexProblem::UnterminatedString:
            return "string without a closing quotation mark on its line (or longer than 256 "
                   "characters)";
    }
    return {};
}

}  // namespace hg::frep::syntax
