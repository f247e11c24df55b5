#pragma once
// Splits an expression into tokens. Blanks (spaces, tabs, line breaks) separate tokens and are
// otherwise ignored, except that the lexer records a blank between a name and '(' so the parser
// can refuse it (ADAMS does not accept one there).

#include <optional>
#include <string>
#include <vector>

#include "expr/expression_error.hpp"

namespace openmss::expr {

enum class TokenKind {
  Number,
  Name,
  LeftParen,
  RightParen,
  Comma,
  Colon,
  Plus,
  Minus,
  Star,
  Slash,
  Power,
  Percent,
  LeftBracket,
  RightBracket,
  End,
};

struct Token {
  TokenKind kind = TokenKind::End;
  int column = 0;       // 1-based column of the first character
  std::string spelled;  // the characters as written
  // Numbers.
  double number = 0.0;          // value, already converted to radians when written with D
  bool integerLiteral = false;  // digits only: no '.', exponent or D
  bool degrees = false;         // written with the trailing D
  // Names.
  std::string upper;         // upper-case spelling
  bool callFollows = false;  // '(' follows immediately
  int blankBeforeParen = 0;  // column of the first blank when blanks then '(' follow
};

// Tokens of `text`, ending with an End token; or the first lexical error.
struct LexResult {
  std::vector<Token> tokens;
  std::optional<ExpressionError> error;
};

LexResult tokenize(const std::string& text);

// Human-readable form of a token for messages: "')'", "'DM'", "the end".
std::string describe(const Token& token);

}  // namespace openmss::expr
