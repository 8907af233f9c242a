// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Tests of Boolean_expression.  The oracles are independent of the code under
// test: expression trees evaluated recursively, and the Blake canonical form
// computed by brute force from the truth table (all 3^n terms, keep the
// implicants none of whose one-literal-shorter terms is an implicant).

#include <CGAL/Boolean_isosurfacing_3/Boolean_expression.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <functional>
#include <iterator>
#include <map>
#include <memory>
#include <random>
#include <set>
#include <string>
#include <vector>

namespace {

using CGAL::Boolean_isosurfacing::Boolean_expression;
using CGAL::Boolean_isosurfacing::Boolean_term;
using CGAL::Boolean_isosurfacing::Expression_value;
using CGAL::Boolean_isosurfacing::Invalid_input_error;
using CGAL::Boolean_isosurfacing::Parse_error;
using CGAL::Boolean_isosurfacing::Variable_naming;
typedef Boolean_expression::Term Term;

Boolean_expression parse(const std::string& s) { return Boolean_expression::parse(s); }

bool contains(const std::string& haystack, const std::string& needle)
{
  return haystack.find(needle) != std::string::npos;
}

// ---------------------------------------------------------------------------
// Oracles

// f as a table over n variables.
typedef std::vector<bool> Table;

Table table_of(const std::function<bool(std::uint64_t)>& f, std::size_t n)
{
  Table t(std::size_t(1) << n);
  for(std::uint64_t s = 0; s < t.size(); ++s)
    t[s] = f(s);
  return t;
}

bool is_implicant(const Table& f, std::size_t n, const Term& t)
{
  for(std::uint64_t s = 0; s < (std::uint64_t(1) << n); ++s)
    if(t.is_satisfied_by(s) && !f[s])
      return false;
  return true;
}

// All prime implicants in canonical order, by brute force over the 3^n terms.
std::vector<Term> brute_force_primes(const Table& f, std::size_t n)
{
  std::vector<Term> primes;
  std::size_t count = 1;
  for(std::size_t i = 0; i < n; ++i)
    count *= 3;
  for(std::size_t code = 0; code < count; ++code)
  {
    Term t;
    std::size_t c = code;
    for(std::size_t v = 0; v < n; ++v, c /= 3)
    {
      if(c % 3 == 1)
        t.pos |= std::uint64_t(1) << v;
      if(c % 3 == 2)
        t.neg |= std::uint64_t(1) << v;
    }
    if(!is_implicant(f, n, t))
      continue;
    bool prime = true;
    for(std::uint64_t bits = t.literals(); bits != 0 && prime; bits &= bits - 1)
    {
      const std::uint64_t bit = bits & (~bits + 1);
      if(is_implicant(f, n, Term{t.pos & ~bit, t.neg & ~bit}))
        prime = false;
    }
    if(prime)
      primes.push_back(t);
  }
  std::sort(primes.begin(), primes.end(), CGAL::Boolean_isosurfacing::internal::canonical_less);
  return primes;
}

// ---------------------------------------------------------------------------
// Random expression trees

enum class Op { VARIABLE, CONSTANT, NOT, AND, OR, MINUS };

struct Tree
{
  Op op;
  std::size_t variable = 0;
  bool value = false;
  std::unique_ptr<Tree> left, right;

  bool evaluate(std::uint64_t s) const
  {
    switch(op)
    {
    case Op::VARIABLE: return ((s >> variable) & 1) != 0;
    case Op::CONSTANT: return value;
    case Op::NOT: return !left->evaluate(s);
    case Op::AND: return left->evaluate(s) && right->evaluate(s);
    case Op::OR: return left->evaluate(s) || right->evaluate(s);
    case Op::MINUS: return left->evaluate(s) && !right->evaluate(s);
    }
    return false;
  }

  // Binding strength in the documented grammar.
  int level() const
  {
    switch(op)
    {
    case Op::OR: return 1;
    case Op::MINUS: return 2;
    case Op::AND: return 3;
    case Op::NOT: return 4;
    default: return 5;
    }
  }
};

class Tree_generator
{
public:
  explicit Tree_generator(unsigned seed) : m_random(seed) {}

  std::unique_ptr<Tree> make(std::size_t n, int depth)
  {
    std::unique_ptr<Tree> t(new Tree);
    const int r = uniform(0, 99);
    if(depth == 0 || r < 15)
    {
      if(uniform(0, 19) == 0)
      {
        t->op = Op::CONSTANT;
        t->value = uniform(0, 1) == 1;
      }
      else
      {
        t->op = Op::VARIABLE;
        t->variable = std::size_t(uniform(0, int(n) - 1));
      }
      return t;
    }
    t->op = r < 30 ? Op::NOT : r < 60 ? Op::AND : r < 85 ? Op::OR : Op::MINUS;
    t->left = make(n, depth - 1);
    if(t->op != Op::NOT)
      t->right = make(n, depth - 1);
    return t;
  }

  // Every binary operation in parentheses; random spellings and spacing.
  std::string full(const Tree& t, const std::vector<std::string>& names)
  {
    switch(t.op)
    {
    case Op::VARIABLE: return space() + names[t.variable] + space();
    case Op::CONSTANT:
      return space() + (uniform(0, 1) ? (t.value ? "1" : "0") : (t.value ? "true" : "false")) + space();
    case Op::NOT: return (uniform(0, 1) ? "!" : "~") + space() + full(*t.left, names);
    default: return "(" + full(*t.left, names) + symbol(t.op) + full(*t.right, names) + ")";
    }
  }

  // Only the parentheses the precedence rules require (binary operators
  // left-associative): exercises the precedence of the parser.
  std::string minimal(const Tree& t, const std::vector<std::string>& names)
  {
    switch(t.op)
    {
    case Op::VARIABLE: return names[t.variable];
    case Op::CONSTANT: return t.value ? "1" : "0";
    case Op::NOT:
      return "!" + wrap(minimal(*t.left, names), t.left->level() < t.level());
    default:
      return wrap(minimal(*t.left, names), t.left->level() < t.level()) + " " + symbol(t.op) +
             " " + wrap(minimal(*t.right, names), t.right->level() <= t.level());
    }
  }

  int uniform(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(m_random); }

private:
  static std::string wrap(const std::string& s, bool parenthesize)
  {
    return parenthesize ? "(" + s + ")" : s;
  }

  static std::string symbol(Op op)
  {
    return op == Op::AND ? "&" : op == Op::OR ? "|" : "-";
  }

  std::string space() { return uniform(0, 3) == 0 ? " " : ""; }

  std::mt19937 m_random;
};

std::vector<std::string> letters(std::size_t n)
{
  std::vector<std::string> names;
  for(std::size_t i = 0; i < n; ++i)
    names.push_back(std::string(1, char('A' + i)));
  return names;
}

std::vector<std::string> f_names(std::size_t n)
{
  std::vector<std::string> names;
  for(std::size_t i = 0; i < n; ++i)
    names.push_back("f" + std::to_string(i));
  return names;
}

std::uint64_t full_mask(std::size_t n) { return (std::uint64_t(1) << n) - 1; }

// ---------------------------------------------------------------------------
// Parsing

TEST(Boolean_expression_parse, single_forms)
{
  EXPECT_EQ(parse("A").terms(), (std::vector<Term>{Term{1, 0}}));
  EXPECT_EQ(parse("!A").terms(), (std::vector<Term>{Term{0, 1}}));
  EXPECT_EQ(parse("~A").terms(), (std::vector<Term>{Term{0, 1}}));
  EXPECT_EQ(parse("A & B").terms(), (std::vector<Term>{Term{3, 0}}));
  EXPECT_EQ(parse("A|B").terms(), (std::vector<Term>{Term{1, 0}, Term{2, 0}}));
  EXPECT_EQ(parse("A - B").terms(), (std::vector<Term>{Term{1, 2}}));
  EXPECT_EQ(parse("  A\t&\n!B \r"), parse("A&!B"));
  EXPECT_EQ(parse("((A))"), parse("A"));
  EXPECT_EQ(parse("!!A"), parse("A"));
  EXPECT_EQ(parse("!~!A"), parse("!A"));
  EXPECT_EQ(parse("A").number_of_variables(), 1u);
  EXPECT_EQ(parse("C").number_of_variables(), 3u);
  EXPECT_EQ(parse("A & !Z").number_of_variables(), 26u);
}

TEST(Boolean_expression_parse, precedence_and_associativity)
{
  // ! > & > - > |, binary operators left-associative.
  EXPECT_EQ(parse("A | B & C"), parse("A | (B & C)"));
  EXPECT_NE(parse("A | B & C"), parse("(A | B) & C"));
  EXPECT_EQ(parse("A - B & C"), parse("A - (B & C)"));
  EXPECT_EQ(parse("A - B & C"), parse("A & !B | A & !C"));
  EXPECT_EQ(parse("A | B - C"), parse("A | (B & !C)"));
  EXPECT_EQ(parse("A - B | C"), parse("(A & !B) | C"));
  EXPECT_EQ(parse("A - B - C"), parse("(A - B) - C"));
  EXPECT_EQ(parse("A - B - C"), parse("A & !B & !C"));
  EXPECT_NE(parse("A - B - C"), parse("A - (B - C)"));
  EXPECT_EQ(parse("A - (B - C)"), parse("A & !B | A & C"));
  EXPECT_EQ(parse("!A & B"), parse("(!A) & B"));
  EXPECT_NE(parse("!A & B"), parse("!(A & B)"));
  EXPECT_EQ(parse("!A | B & !C"), parse("(!A) | (B & (!C))"));
}

TEST(Boolean_expression_parse, de_morgan_and_distribution)
{
  EXPECT_EQ(parse("!(A | B)"), parse("!A & !B"));
  EXPECT_EQ(parse("!(A & B)"), parse("!A | !B"));
  EXPECT_EQ(parse("!(A - B)"), parse("!A | B"));
  EXPECT_EQ(parse("!(!A & (B | !C))"), parse("A | !B & C"));
  const Boolean_expression e = parse("(A | B) & (C | D)");
  EXPECT_EQ(e.number_of_terms(), 4u);
  EXPECT_EQ(e, parse("A&C | A&D | B&C | B&D"));
  EXPECT_EQ(e.to_string(), "A & C | A & D | B & C | B & D");
}

TEST(Boolean_expression_parse, constants)
{
  EXPECT_TRUE(parse("0").is_false());
  EXPECT_TRUE(parse("false").is_false());
  EXPECT_TRUE(parse("1").is_true());
  EXPECT_TRUE(parse("true").is_true());
  EXPECT_TRUE(parse("!0").is_true());
  EXPECT_TRUE(parse("~true").is_false());
  EXPECT_TRUE(parse("A & 0").is_false());
  EXPECT_TRUE(parse("A | 1").is_true());
  EXPECT_EQ(parse("A & true"), parse("A"));
  EXPECT_EQ(parse("A | false"), parse("A"));
  EXPECT_TRUE(parse("A & !A").is_false());
  EXPECT_TRUE(parse("A | !A").is_true());
  EXPECT_EQ(parse("1").number_of_variables(), 0u);
  EXPECT_EQ(parse("0").to_string(), "false");
  EXPECT_EQ(parse("1").to_string(), "true");
  EXPECT_EQ(parse("true").terms(), (std::vector<Term>{Term{0, 0}}));
  EXPECT_TRUE(parse("false").terms().empty());
}

TEST(Boolean_expression_parse, naming_conventions)
{
  const Boolean_expression f = parse("f0 & !f3 | f10");
  EXPECT_EQ(f.naming(), Variable_naming::INDEXED_F);
  EXPECT_EQ(f.number_of_variables(), 11u);
  EXPECT_EQ(f.to_string(), "f0 & !f3 | f10");
  EXPECT_EQ(parse("f63").number_of_variables(), 64u);
  EXPECT_EQ(parse("f007"), parse("f7"));

  const Boolean_expression l = parse("B & !D");
  EXPECT_EQ(l.naming(), Variable_naming::CAPITAL_LETTERS);
  EXPECT_EQ(l.number_of_variables(), 4u);
  EXPECT_EQ(l.to_string(), "B & !D");
  EXPECT_EQ(l, parse("f1 & !f3")); // same function, other spelling

  const std::vector<std::string> names{"outer", "inner", "_cut2"};
  const Boolean_expression x = Boolean_expression::parse("inner & !outer | _cut2", names);
  EXPECT_EQ(x.naming(), Variable_naming::EXPLICIT_NAMES);
  EXPECT_EQ(x.number_of_variables(), 3u);
  EXPECT_EQ(x.terms(), (std::vector<Term>{Term{2, 1}, Term{4, 0}}));
  EXPECT_EQ(x.to_string(), "!outer & inner | _cut2");
  EXPECT_EQ(Boolean_expression::parse(x.to_string(), names), x);
  // Explicit names may look like the automatic ones and mean something else.
  EXPECT_EQ(Boolean_expression::parse("f0", {"A", "f0"}).terms(), (std::vector<Term>{Term{2, 0}}));
  EXPECT_EQ(Boolean_expression::parse("1", {}).number_of_variables(), 0u);
}

TEST(Boolean_expression_parse, long_inputs_do_not_recurse)
{
  std::string chain = "A";
  for(int i = 0; i < 20000; ++i)
    chain += i % 2 ? " | A" : " & A";
  EXPECT_EQ(parse(chain), parse("A"));
  EXPECT_EQ(parse(std::string(100001, '!') + "A"), parse("!A"));
  const std::size_t depth = Boolean_expression::max_nesting_depth;
  EXPECT_EQ(parse(std::string(depth, '(') + "A" + std::string(depth, ')')), parse("A"));
}

// ---------------------------------------------------------------------------
// Factories and the seed's CSG_STATE

// The seed's pseudocode, transcribed.
enum class Csg_op { UNION, INTERSECTION, DIFFERENCE };
bool csg_state(Csg_op op, bool pA, bool pB)
{
  bool result = false;
  if(op == Csg_op::UNION && (pA == true || pB == true))
    result = true;
  if(op == Csg_op::INTERSECTION && pA == true && pB == true)
    result = true;
  if(op == Csg_op::DIFFERENCE && pA == true && pB == false)
    result = true;
  return result;
}

TEST(Boolean_expression_factories, seed_csg_state)
{
  const Boolean_expression u = Boolean_expression::union_of(2);
  const Boolean_expression i = Boolean_expression::intersection_of(2);
  const Boolean_expression d = Boolean_expression::difference();
  for(std::uint64_t s = 0; s < 4; ++s)
  {
    const bool pA = (s & 1) != 0, pB = (s & 2) != 0;
    EXPECT_EQ(u.evaluate(s), csg_state(Csg_op::UNION, pA, pB)) << s;
    EXPECT_EQ(i.evaluate(s), csg_state(Csg_op::INTERSECTION, pA, pB)) << s;
    EXPECT_EQ(d.evaluate(s), csg_state(Csg_op::DIFFERENCE, pA, pB)) << s;
  }
  EXPECT_EQ(u, parse("A | B"));
  EXPECT_EQ(i, parse("A & B"));
  EXPECT_EQ(d, parse("A - B"));
}

TEST(Boolean_expression_factories, n_ary_and_printing)
{
  EXPECT_EQ(Boolean_expression::union_of(3).to_string(), "A | B | C");
  EXPECT_EQ(Boolean_expression::intersection_of(3).to_string(), "A & B & C");
  EXPECT_EQ(Boolean_expression::difference().to_string(), "A & !B");
  EXPECT_EQ(Boolean_expression::single(2, 4).to_string(), "C");
  EXPECT_EQ(Boolean_expression::single(2, 4).number_of_variables(), 4u);
  EXPECT_TRUE(Boolean_expression::union_of(0).is_false());
  EXPECT_TRUE(Boolean_expression::intersection_of(0).is_true());
  EXPECT_TRUE(Boolean_expression::constant(true, 3).is_true());
  EXPECT_TRUE(Boolean_expression().is_false());
  // Beyond 26 variables the letters run out: f<k> naming, still round-trips.
  const Boolean_expression big = Boolean_expression::union_of(64);
  EXPECT_EQ(big.naming(), Variable_naming::INDEXED_F);
  EXPECT_EQ(big.number_of_terms(), 64u);
  EXPECT_EQ(parse(big.to_string()), big);
  EXPECT_EQ(parse(big.to_string()).number_of_variables(), 64u);
  EXPECT_TRUE(Boolean_expression::intersection_of(64).evaluate(~std::uint64_t(0)));
  EXPECT_FALSE(Boolean_expression::intersection_of(64).evaluate(~std::uint64_t(0) >> 1));
}

TEST(Boolean_expression_factories, from_terms_normalises)
{
  // The empty term is true and absorbs everything.
  EXPECT_TRUE(Boolean_expression(3, {Term{1, 0}, Term{2, 1}, Term{0, 0}}).is_true());
  // Contradictory (A & !A), duplicate and absorbed (A & B & C) terms go; the
  // consensus B & C of A & B and !A & C is added; the order is canonical.
  const Boolean_expression f(3, {Term{4, 1}, Term{1, 1}, Term{3, 0}, Term{3, 0}, Term{7, 0}});
  EXPECT_EQ(f.to_string(), "A & B | !A & C | B & C");
  EXPECT_EQ(f, parse("A & B | !A & C"));
  EXPECT_EQ(f.support(), 7u);
  const Boolean_expression g(2, {Term{1, 0}, Term{0, 1}});
  EXPECT_TRUE(g.is_true()); // consensus of A and !A
}

TEST(Boolean_expression_factories, evaluate_ignores_unused_bits)
{
  const Boolean_expression e = parse("A & !B");
  EXPECT_TRUE(e.evaluate(1 | (std::uint64_t(1) << 40)));
  EXPECT_FALSE(e.evaluate(3));
}

// ---------------------------------------------------------------------------
// Errors

template <typename Error, typename F>
Error expect_throw(F f)
{
  try
  {
    f();
  }
  catch(const Error& e)
  {
    return e;
  }
  catch(const std::exception& e)
  {
    ADD_FAILURE() << "wrong exception type: " << e.what();
    throw;
  }
  ADD_FAILURE() << "no exception";
  throw std::logic_error("no exception");
}

void expect_parse_error(const std::string& text, std::size_t position, const std::string& substring,
                        const std::vector<std::string>* names = nullptr)
{
  SCOPED_TRACE(text);
  const Parse_error e = expect_throw<Parse_error>(
      [&] { return names ? Boolean_expression::parse(text, *names) : Boolean_expression::parse(text); });
  EXPECT_EQ(e.position(), position) << e.what();
  EXPECT_TRUE(contains(e.what(), substring)) << e.what();
  // The message shows where: the 1-based column and the text.
  EXPECT_TRUE(contains(e.what(), "at column " + std::to_string(position + 1))) << e.what();
  const bool printable = std::all_of(text.begin(), text.end(), [](char c) { return c >= ' '; });
  EXPECT_TRUE(!printable || contains(e.what(), "\"" + text + "\"")) << e.what();
}

TEST(Boolean_expression_errors, syntax)
{
  expect_parse_error("", 0, "empty Boolean expression");
  expect_parse_error("  \t ", 0, "empty Boolean expression");
  expect_parse_error("A & )B", 4, "unexpected ')'");
  expect_parse_error("(A & B", 6, "missing ')'");
  expect_parse_error("((A & B) | C", 12, "the '(' at column 1 is not closed");
  expect_parse_error("A & B)", 5, "unmatched ')'");
  expect_parse_error("A &", 3, "unexpected end of expression");
  expect_parse_error("A | !", 5, "unexpected end of expression");
  expect_parse_error("& A", 0, "unexpected '&'");
  expect_parse_error("A | | B", 4, "unexpected '|'");
  expect_parse_error("A B", 2, "unexpected identifier 'B'");
  expect_parse_error("(A) (B)", 4, "unexpected '('");
  expect_parse_error("()", 1, "unexpected ')'");
  expect_parse_error("A # B", 2, "unexpected character '#'");
  expect_parse_error("A && B", 3, "unexpected '&'");
  expect_parse_error("A & 2", 4, "unexpected '2'");
  expect_parse_error("A & 10", 4, "only numeric constants are 0 and 1");
  expect_parse_error(std::string(Boolean_expression::max_nesting_depth + 1, '(') + "A" +
                         std::string(Boolean_expression::max_nesting_depth + 1, ')'),
                     Boolean_expression::max_nesting_depth, "nested deeper than 256");
}

TEST(Boolean_expression_errors, identifiers)
{
  expect_parse_error("a & b", 0, "unknown variable 'a'");
  expect_parse_error("A & AB", 4, "unknown variable 'AB'");
  expect_parse_error("A | f", 4, "unknown variable 'f'");
  expect_parse_error("A & !f1", 5, "variable 'f1' mixes naming conventions with 'A' (column 1)");
  expect_parse_error("f2 | (B)", 6, "mixes naming conventions");
  expect_parse_error("f0 | f64", 5, "variable index too large in 'f64'");
  expect_parse_error("f99999999999999999999999", 0, "variable index too large");
  const std::vector<std::string> names{"x", "z"};
  expect_parse_error("x & y", 4, "unknown variable 'y'", &names);
  expect_parse_error("x & y", 4, "the variables are x, z", &names);
  expect_parse_error("A", 0, "unknown variable 'A'", &names);
  const std::vector<std::string> none;
  expect_parse_error("A", 0, "no variable names were given", &none);
}

TEST(Boolean_expression_errors, misuse)
{
  std::vector<std::string> many;
  for(int i = 0; i < 65; ++i)
    many.push_back("v" + std::to_string(i));
  Invalid_input_error e = expect_throw<Invalid_input_error>([&] { Boolean_expression::parse("v0", many); });
  EXPECT_TRUE(contains(e.what(), "at most 64 variables, 65 names given")) << e.what();
  many.pop_back();
  EXPECT_EQ(Boolean_expression::parse("v63", many).number_of_variables(), 64u);

  e = expect_throw<Invalid_input_error>([] { Boolean_expression::parse("a", {"a", "b", "a"}); });
  EXPECT_TRUE(contains(e.what(), "\"a\" is given twice (#0 and #2)")) << e.what();
  e = expect_throw<Invalid_input_error>([] { Boolean_expression::parse("a", {"a", "b c"}); });
  EXPECT_TRUE(contains(e.what(), "#1 \"b c\" is not an identifier")) << e.what();
  e = expect_throw<Invalid_input_error>([] { Boolean_expression::parse("a", {"a", "true"}); });
  EXPECT_TRUE(contains(e.what(), "\"true\" is not an identifier")) << e.what();
  e = expect_throw<Invalid_input_error>([] { Boolean_expression::parse("a", {"a", "1x"}); });
  EXPECT_TRUE(contains(e.what(), "\"1x\" is not an identifier")) << e.what();

  e = expect_throw<Invalid_input_error>([] { Boolean_expression::union_of(65); });
  EXPECT_TRUE(contains(e.what(), "at most 64 variables, 65 requested")) << e.what();
  e = expect_throw<Invalid_input_error>([] { Boolean_expression::single(3, 3); });
  EXPECT_TRUE(contains(e.what(), "variable 3 does not exist")) << e.what();
  e = expect_throw<Invalid_input_error>([] { Boolean_expression(2, {Term{4, 0}}); });
  EXPECT_TRUE(contains(e.what(), "term #0 uses variable 2")) << e.what();
  e = expect_throw<Invalid_input_error>([] { Boolean_expression::union_of(27).truth_table(); });
  EXPECT_TRUE(contains(e.what(), "at most 26")) << e.what();
  e = expect_throw<Invalid_input_error>([] { parse("A & B").derivative(2); });
  EXPECT_TRUE(contains(e.what(), "variable 2 of an expression of 2 variables")) << e.what();
}

std::string pairs_product(std::size_t pairs)
{
  std::string s;
  for(std::size_t i = 0; i < pairs; ++i)
    s += std::string(i ? " & " : "") + "(" + char('A' + 2 * i) + " | " + char('B' + 2 * i) + ")";
  return s;
}

TEST(Boolean_expression_errors, blow_up_limit)
{
  ASSERT_EQ(Boolean_expression::max_terms, 4096u);
  // 2^12 = 4096 prime implicants: exactly at the limit, accepted.
  EXPECT_EQ(parse(pairs_product(12)).number_of_terms(), 4096u);
  // One term more is one too many.
  Invalid_input_error e0 = expect_throw<Invalid_input_error>([] { parse(pairs_product(12) + " | Y"); });
  EXPECT_TRUE(contains(e0.what(), "more than 4096 terms")) << e0.what();
  // 2^13: refused, with the limit and the place in the message, and not as a syntax error.
  Invalid_input_error e = expect_throw<Invalid_input_error>([] { parse(pairs_product(13)); });
  EXPECT_TRUE(contains(e.what(), "more than 4096 terms")) << e.what();
  EXPECT_TRUE(contains(e.what(), "sub-expression starting at column 1")) << e.what();
  bool is_syntax_error = false;
  try
  {
    parse(pairs_product(13));
  }
  catch(const Parse_error&)
  {
    is_syntax_error = true;
  }
  catch(const Invalid_input_error&)
  {
  }
  EXPECT_FALSE(is_syntax_error);

  // The same blow-up reached through De Morgan.
  std::string sum = "!(";
  for(std::size_t i = 0; i < 13; ++i)
    sum += std::string(i ? " | " : "") + char('A' + 2 * i) + " & " + char('B' + 2 * i);
  sum += ")";
  e = expect_throw<Invalid_input_error>([&] { parse(sum); });
  EXPECT_TRUE(contains(e.what(), "more than 4096 terms")) << e.what();
  EXPECT_TRUE(contains(e.what(), "column 3")) << e.what();

  // And through the operators.
  const Boolean_expression p = parse(pairs_product(7)), q = Boolean_expression::parse(
      "(f14 | f15) & (f16 | f17) & (f18 | f19) & (f20 | f21) & (f22 | f23)");
  EXPECT_EQ((p & q).number_of_terms(), 4096u); // 2^7 * 2^5: at the limit
  const Boolean_expression r = p & Boolean_expression::parse("f26 | f27");
  e = expect_throw<Invalid_input_error>([&] { return r & q; });
  EXPECT_TRUE(contains(e.what(), "the intersection would have more than 4096 terms")) << e.what();
}

// ---------------------------------------------------------------------------
// Semantics against random expression trees

TEST(Boolean_expression_semantics, random_trees_match_recursive_evaluation)
{
  Tree_generator gen(20260101u);
  for(int iteration = 0; iteration < 10000; ++iteration)
  {
    const std::size_t n = std::size_t(gen.uniform(1, 6));
    const std::unique_ptr<Tree> tree = gen.make(n, gen.uniform(1, 5));
    const int style = gen.uniform(0, 2);
    const std::vector<std::string> names = style == 0 ? letters(n) : style == 1 ? f_names(n)
                                           : std::vector<std::string>{"alpha", "b2", "_c", "d", "e_", "F"};
    const std::string full = gen.full(*tree, names), minimal = gen.minimal(*tree, names);
    SCOPED_TRACE(full);
    SCOPED_TRACE(minimal);
    const Boolean_expression e = style == 2 ? Boolean_expression::parse(full, names)
                                            : Boolean_expression::parse(full);
    const Boolean_expression m = style == 2 ? Boolean_expression::parse(minimal, names)
                                            : Boolean_expression::parse(minimal);
    const Table expected = table_of([&](std::uint64_t s) { return tree->evaluate(s); }, n);
    for(std::uint64_t s = 0; s < expected.size(); ++s)
      ASSERT_EQ(e.evaluate(s), bool(expected[s])) << "state " << s;
    // Canonical form = all prime implicants, exactly, so equivalent texts give equal objects.
    ASSERT_EQ(e.terms(), brute_force_primes(expected, n)) << e.to_string();
    ASSERT_EQ(m, e) << m.to_string() << " vs " << e.to_string();
    // No term is contradictory, none absorbs another, support is exact.
    std::uint64_t support = 0;
    for(std::size_t a = 0; a < e.terms().size(); ++a)
    {
      ASSERT_EQ(e.terms()[a].pos & e.terms()[a].neg, 0u);
      support |= e.terms()[a].literals();
      for(std::size_t b = 0; b < e.terms().size(); ++b)
      {
        if(a != b)
        {
          ASSERT_FALSE(CGAL::Boolean_isosurfacing::internal::absorbs(e.terms()[a], e.terms()[b]));
        }
      }
    }
    ASSERT_EQ(e.support(), support);
    // Round trip through text.
    const Boolean_expression back = style == 2 ? Boolean_expression::parse(e.to_string(), names)
                                               : Boolean_expression::parse(e.to_string());
    ASSERT_EQ(back, e) << e.to_string();
    // Truth table.
    const std::vector<bool> table = e.truth_table();
    ASSERT_EQ(table.size(), std::size_t(1) << e.number_of_variables());
    for(std::uint64_t s = 0; s < table.size(); ++s)
      ASSERT_EQ(bool(table[s]), e.evaluate(s));
  }
}

TEST(Boolean_expression_semantics, equivalent_texts_give_equal_objects)
{
  // Over 3 variables there are only 256 functions: thousands of random trees
  // collide, and every collision must give the same object.
  Tree_generator gen(7u);
  std::map<std::vector<bool>, Boolean_expression> by_function;
  std::size_t collisions = 0;
  for(int iteration = 0; iteration < 4000; ++iteration)
  {
    const std::unique_ptr<Tree> tree = gen.make(3, gen.uniform(1, 5));
    const Boolean_expression e = Boolean_expression::parse(gen.full(*tree, f_names(3)));
    const Table table = table_of([&](std::uint64_t s) { return tree->evaluate(s); }, 3);
    const auto inserted = by_function.insert(std::make_pair(table, e));
    if(!inserted.second)
    {
      ++collisions;
      ASSERT_EQ(inserted.first->second, e) << inserted.first->second << " vs " << e;
    }
  }
  EXPECT_GT(collisions, 3000u);
  EXPECT_GT(by_function.size(), 60u);
  // And distinct functions give distinct objects.
  std::set<std::string> texts;
  for(const auto& entry : by_function)
    texts.insert(entry.second.to_string());
  EXPECT_EQ(texts.size(), by_function.size());
}

TEST(Boolean_expression_semantics, operators)
{
  Tree_generator gen(99u);
  for(int iteration = 0; iteration < 2000; ++iteration)
  {
    const std::size_t n = std::size_t(gen.uniform(1, 5));
    const Boolean_expression a = parse(gen.full(*gen.make(n, 4), letters(n)));
    const Boolean_expression b = parse(gen.full(*gen.make(n, 4), letters(n)));
    const Boolean_expression not_a = !a, both = a & b, either = a | b, minus = a - b;
    const std::size_t m = std::max(a.number_of_variables(), b.number_of_variables());
    for(std::uint64_t s = 0; s < (std::uint64_t(1) << m); ++s)
    {
      ASSERT_EQ(not_a.evaluate(s), !a.evaluate(s));
      ASSERT_EQ(both.evaluate(s), a.evaluate(s) && b.evaluate(s));
      ASSERT_EQ(either.evaluate(s), a.evaluate(s) || b.evaluate(s));
      ASSERT_EQ(minus.evaluate(s), a.evaluate(s) && !b.evaluate(s));
    }
    ASSERT_EQ(both.terms(), brute_force_primes(
        table_of([&](std::uint64_t s) { return both.evaluate(s); }, m), m));
    ASSERT_EQ(both.number_of_variables(), m);
  }
}

// ---------------------------------------------------------------------------
// Partial evaluation, restriction, derivative

TEST(Boolean_expression_partial, agrees_with_brute_force_for_all_known_masks)
{
  Tree_generator gen(31337u);
  std::vector<std::size_t> undecided;
  for(int iteration = 0; iteration < 600; ++iteration)
  {
    const std::size_t n = std::size_t(gen.uniform(1, 5));
    const std::unique_ptr<Tree> tree = gen.make(n, gen.uniform(2, 5));
    const Boolean_expression e = Boolean_expression::parse(gen.full(*tree, letters(n)), letters(n));
    SCOPED_TRACE(e.to_string());
    const std::uint64_t all = full_mask(n);
    for(std::uint64_t known = 0; known <= all; ++known)
      for(std::uint64_t state = 0; state <= all; ++state)
      {
        if((state & ~known) != 0)
          continue; // the unknown bits of state must not matter: checked below
        bool some_true = false, some_false = false;
        for(std::uint64_t s = 0; s <= all; ++s)
          if((s & known) == state)
            (tree->evaluate(s) ? some_true : some_false) = true;
        const Expression_value expected = some_true && some_false ? Expression_value::UNDECIDED
                                          : some_true              ? Expression_value::ALWAYS_TRUE
                                                                   : Expression_value::ALWAYS_FALSE;
        ASSERT_EQ(e.partially_evaluate(known, state), expected) << known << " " << state;
        ASSERT_EQ(e.partially_evaluate(known, state | (~known & all)), expected);

        undecided.clear();
        ASSERT_EQ(e.partially_evaluate(known, state, std::back_inserter(undecided)), expected);
        if(expected == Expression_value::UNDECIDED)
        {
          std::vector<std::size_t> brute;
          for(std::size_t k = 0; k < e.terms().size(); ++k)
          {
            const Term& t = e.terms()[k];
            if(((state ^ t.pos) & t.literals() & known) == 0 && (t.literals() & ~known) != 0)
              brute.push_back(k);
          }
          ASSERT_EQ(undecided, brute);
        }

        const Boolean_expression r = e.restrict(known, state);
        ASSERT_EQ(r.support() & known, 0u);
        ASSERT_EQ(r.number_of_variables(), e.number_of_variables());
        const Table restricted =
            table_of([&](std::uint64_t s) { return tree->evaluate((s & ~known) | state); }, n);
        ASSERT_EQ(r.terms(), brute_force_primes(restricted, n)) << r.to_string();
        ASSERT_EQ(r.is_true(), expected == Expression_value::ALWAYS_TRUE);
        ASSERT_EQ(r.is_false(), expected == Expression_value::ALWAYS_FALSE);
      }
  }
}

TEST(Boolean_expression_partial, derivative_and_support)
{
  Tree_generator gen(4242u);
  for(int iteration = 0; iteration < 2000; ++iteration)
  {
    const std::size_t n = std::size_t(gen.uniform(1, 6));
    const std::unique_ptr<Tree> tree = gen.make(n, gen.uniform(1, 5));
    const Boolean_expression e = Boolean_expression::parse(gen.full(*tree, f_names(n)), f_names(n));
    SCOPED_TRACE(e.to_string());
    const std::uint64_t all = full_mask(n);
    std::uint64_t support = 0;
    for(std::size_t i = 0; i < n; ++i)
    {
      const std::uint64_t bit = std::uint64_t(1) << i;
      const Boolean_expression d = e.derivative(i);
      ASSERT_EQ(d.support() & bit, 0u); // the derivative does not depend on x_i
      bool changes = false;
      for(std::uint64_t s = 0; s <= all; ++s)
      {
        const bool flips = tree->evaluate(s | bit) != tree->evaluate(s & ~bit);
        changes = changes || flips;
        ASSERT_EQ(d.evaluate(s), flips) << "variable " << i << " state " << s;
      }
      ASSERT_EQ(e.depends_on(i), changes) << i;
      ASSERT_EQ(d.is_false(), !changes);
      if(changes)
        support |= bit;
    }
    ASSERT_EQ(e.support(), support);
  }
  // A worked example: A & B | !A & C.
  const Boolean_expression e = parse("A & B | !A & C");
  EXPECT_EQ(e.derivative(0), parse("B & !C | !B & C")); // the faces on A: where B and C differ
  EXPECT_EQ(e.derivative(1), parse("A"));
  EXPECT_EQ(e.derivative(2), parse("!A"));
  EXPECT_FALSE(parse("A | !A & B | B").depends_on(63));
}

} // namespace

// ---------------------------------------------------------------------------
// Parsing cost (issue 12): a 4 KB product at the term limit whose further
// operands are redundant used to cost one absorption of the whole product per
// operand, 3 to 14 s in all; now each redundant operand is one linear pass.

namespace {
double seconds_to_parse(const std::string& text, std::size_t& terms)
{
  const auto start = std::chrono::steady_clock::now();
  terms = parse(text).number_of_terms();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}
} // namespace

TEST(Boolean_expression_cost, redundant_operands_of_a_product_at_the_limit)
{
  const std::vector<std::string> operands = {" & (A | B)", " & (A | B | C)", " & (A | C | E | G | I | K | M | O | Q | S | U | W)",
                                             " | A & C & E"};
  for(const std::string& operand : operands)
  {
    std::string text = pairs_product(12);
    while(text.size() < 4000)
      text += operand;
    SCOPED_TRACE(operand);
    std::size_t terms = 0;
    const double seconds = seconds_to_parse(text, terms);
    EXPECT_LT(seconds, 1.0) << text.size() << " bytes";
    EXPECT_GE(terms, 3585u);
    EXPECT_LE(terms, 4096u);
  }
  // The product repeated: every operand is the product itself.
  std::string text = "(" + pairs_product(12) + ")";
  const std::string factor = text;
  while(text.size() < 4000)
    text += " & " + factor;
  std::size_t terms = 0;
  EXPECT_LT(seconds_to_parse(text, terms), 1.0);
  EXPECT_EQ(terms, 4096u);
  EXPECT_EQ(parse(text), parse(pairs_product(12)));
}

TEST(Boolean_expression_cost, the_work_limit_is_an_error_not_a_hang)
{
  // Operands that each need a real absorption of a 2048-term product.
  std::string text = pairs_product(11);
  for(int i = 0; text.size() < 60000; ++i)
    text += std::string(" & (Y | ") + char('A' + 2 * (i % 11)) + ")";
  const auto start = std::chrono::steady_clock::now();
  try
  {
    const std::size_t terms = parse(text).number_of_terms();
    EXPECT_EQ(terms, 2048u);
  }
  catch(const Invalid_input_error& e)
  {
    EXPECT_TRUE(contains(e.what(), "term comparisons (the limit of Boolean_expression)")) << e.what();
  }
  // Generous (a shared, loaded machine): the point is no hang.
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 3.0);
}
