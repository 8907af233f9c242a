// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_BOOLEAN_EXPRESSION_H
#define CGAL_BOOLEAN_ISOSURFACING_3_BOOLEAN_EXPRESSION_H

// This header deliberately needs nothing but the standard library: it is
// shared by the mesh CSG tool, TBISO and their command-line front ends, and
// it is the one component that must be usable (and testable) without CGAL.

#include <CGAL/Boolean_isosurfacing_3/exceptions.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Boolean_isosurfacing {

/// \ingroup PkgBooleanIsosurfacing3Ref
/// The value of a Boolean expression when only some variables are known
/// (see `Boolean_expression::partially_evaluate()`).
enum class Expression_value
{
  ALWAYS_FALSE, ///< false whatever the unknown variables are
  ALWAYS_TRUE,  ///< true whatever the unknown variables are
  UNDECIDED     ///< depends on at least one unknown variable
};

/// \ingroup PkgBooleanIsosurfacing3Ref
/// How `Boolean_expression::to_string()` names variable `i`.
enum class Variable_naming
{
  CAPITAL_LETTERS, ///< `A` = 0, `B` = 1, ... `Z` = 25 (the CSG tool: input meshes in order)
  INDEXED_F,       ///< `f0`, `f1`, ... `f63` (TBISO: field `i`)
  EXPLICIT_NAMES   ///< the names given to `Boolean_expression::parse(text, names)`
};

/// \ingroup PkgBooleanIsosurfacing3Ref
/// One conjunction of literals.  Bit `i` of `pos` is the literal "inside
/// variable `i`", bit `i` of `neg` the literal "outside variable `i`".  In a
/// `Boolean_expression` `pos & neg == 0` always holds; the term with no
/// literal is the constant `true`.
struct Boolean_term
{
  std::uint64_t pos = 0;
  std::uint64_t neg = 0;

  std::uint64_t literals() const { return pos | neg; }

  /// true iff every literal of the term holds in `state` (bit `i` set = inside variable `i`).
  bool is_satisfied_by(std::uint64_t state) const { return (state & (pos | neg)) == pos; }

  friend bool operator==(const Boolean_term& a, const Boolean_term& b)
  {
    return a.pos == b.pos && a.neg == b.neg;
  }
  friend bool operator!=(const Boolean_term& a, const Boolean_term& b) { return !(a == b); }
};

namespace internal {

// Limits, documented in doc/Boolean_isosurfacing_3/boolean_expression.md.
constexpr std::size_t max_expression_variables = 64;
// Above this, a DNF is no longer a sensible input for per-cell evaluation
// (every cell would scan thousands of terms), and conversions that overshoot
// it are usually the exponential blow-up of distributing & over |.
constexpr std::size_t max_dnf_terms = 4096;
// Bound on the *raw* candidates of one product or consensus step, before
// absorption: it keeps the quadratic absorption pass under a second even in
// the worst case, while still letting heavily redundant products (which
// absorb back to a few terms) through.
constexpr std::size_t max_dnf_candidates = 64 * max_dnf_terms;
// 2^26 bits = 8 MiB: beyond this a truth table is a memory hazard rather
// than an acceleration.
constexpr std::size_t max_truth_table_variables = 26;
// Bounds the recursion of the parser and of the DNF conversion, so that a
// hostile "((((((...))))))" is an error message and not a stack overflow.
constexpr std::size_t max_nesting_depth = 256;

inline int popcount64(std::uint64_t x)
{
#if defined(__GNUC__) || defined(__clang__)
  return __builtin_popcountll(x);
#else
  int n = 0;
  for(; x != 0; x &= x - 1)
    ++n;
  return n;
#endif
}

// Precondition: x != 0.
inline int lowest_bit_index(std::uint64_t x)
{
#if defined(__GNUC__) || defined(__clang__)
  return __builtin_ctzll(x);
#else
  int i = 0;
  while((x & 1) == 0)
  {
    x >>= 1;
    ++i;
  }
  return i;
#endif
}

inline std::uint64_t low_bits_mask(std::size_t n)
{
  return n >= 64 ? ~std::uint64_t(0) : (std::uint64_t(1) << n) - 1;
}

// `general` absorbs `special` when every literal of `general` is a literal of
// `special`: then special implies general and special is redundant in a sum.
inline bool absorbs(const Boolean_term& general, const Boolean_term& special)
{
  return (general.pos & ~special.pos) == 0 && (general.neg & ~special.neg) == 0;
}

inline bool is_contradictory(const Boolean_term& t) { return (t.pos & t.neg) != 0; }

// The canonical order is the lexicographic order of the literal sequences
// (variables ascending, a positive literal before the negative one of the
// same variable, a prefix first).  It is a total order on terms, so sorting
// makes the representation unique, and it prints the way people write
// ("A & B | !A & C | B & C").
inline bool canonical_less(const Boolean_term& a, const Boolean_term& b)
{
  const std::uint64_t diff = (a.pos ^ b.pos) | (a.neg ^ b.neg);
  if(diff == 0)
    return false;
  const int v = lowest_bit_index(diff);
  const std::uint64_t bit = std::uint64_t(1) << v;
  const std::uint64_t above = (v == 63) ? 0 : ~((bit << 1) - 1);
  const bool a_has = (a.literals() & bit) != 0;
  const bool b_has = (b.literals() & bit) != 0;
  if(a_has && b_has)
    return (a.pos & bit) != 0;
  if(a_has) // b continues with a later variable (a first) or ends (b is a prefix of a)
    return (b.literals() & above) != 0;
  return (a.literals() & above) == 0;
}

inline void sort_canonically(std::vector<Boolean_term>& terms)
{
  std::sort(terms.begin(), terms.end(), canonical_less);
}

// Bounds the total work of absorption (pairs of terms compared) in one
// parse: each step is already bounded (candidates x kept terms), but a long
// text can chain thousands of steps.  2^27 comparisons take about half a
// second; the 4 KB products at the term limit of the tests need 0.5 to 26
// million.
constexpr std::size_t max_absorption_work = std::size_t(1) << 27;

struct Absorption_budget
{
  std::size_t spent = 0;
  bool exhausted = false;

  // Charges `work` comparisons; false (and exhausted) beyond the budget.
  bool charge(std::size_t work)
  {
    spent += work;
    if(spent > max_absorption_work)
      exhausted = true;
    return !exhausted;
  }
};

inline bool literal_count_less(const Boolean_term& a, const Boolean_term& b)
{
  const int ca = popcount64(a.literals()), cb = popcount64(b.literals());
  if(ca != cb)
    return ca < cb;
  return a.pos != b.pos ? a.pos < b.pos : a.neg < b.neg;
}

// Removes contradictory, duplicate and absorbed terms.  Returns false (terms
// then unspecified) as soon as more than `limit` terms survive, or when the
// budget is exhausted.
// Sorting by literal count first means a term can only be absorbed by a term
// that is already kept and has fewer literals (duplicates are gone), so one
// pass over that prefix of the kept terms suffices.
inline bool absorb(std::vector<Boolean_term>& terms,
                   std::size_t limit = std::numeric_limits<std::size_t>::max(),
                   Absorption_budget* budget = nullptr)
{
  terms.erase(std::remove_if(terms.begin(), terms.end(), is_contradictory), terms.end());
  std::sort(terms.begin(), terms.end(), literal_count_less);
  terms.erase(std::unique(terms.begin(), terms.end()), terms.end());
  std::size_t kept = 0;
  std::size_t fewer = 0; // kept terms with fewer literals than terms[i]
  int fewer_count = -1;  // their literal count bound
  for(std::size_t i = 0; i < terms.size(); ++i)
  {
    const int count = popcount64(terms[i].literals());
    if(count != fewer_count)
    {
      fewer = kept;
      fewer_count = count;
    }
    if(budget != nullptr && !budget->charge(fewer))
      return false;
    bool absorbed = false;
    for(std::size_t j = 0; j < fewer && !absorbed; ++j)
      absorbed = absorbs(terms[j], terms[i]);
    if(absorbed)
      continue;
    if(kept == limit)
      return false;
    terms[kept++] = terms[i];
  }
  terms.resize(kept);
  return true;
}

// Whether some term of `sorted` (sorted by literal_count_less) absorbs `t`;
// adds the comparisons made to `work`.
inline bool is_absorbed_by_any(const Boolean_term& t, const std::vector<Boolean_term>& sorted, std::size_t& work)
{
  // The frequent redundant case, t itself in the set, by binary search first.
  if(std::binary_search(sorted.begin(), sorted.end(), t, literal_count_less))
    return true;
  const int count = popcount64(t.literals());
  for(const Boolean_term& g : sorted)
  {
    if(popcount64(g.literals()) >= count)
      break; // only fewer literals can absorb a different term
    ++work;
    if(absorbs(g, t))
      return true;
  }
  return false;
}

// DNF of (a & b): the pairwise conjunctions.  Both inputs absorbed (no
// contradictory, duplicate or absorbed term).
// A term x of a that is absorbed by a term y of b gives x & y = x, which
// absorbs every other x & y': it is kept alone, without multiplying it out.
// Such a term is never absorbed by another candidate (that would take
// x' <= x for another term x' of a), so only the products need absorbing.
// This makes a redundant operand ("... & (A | B)" where every term already
// has A or B) one linear pass instead of an absorption of the whole product.
inline bool dnf_and(const std::vector<Boolean_term>& a, const std::vector<Boolean_term>& b,
                    std::vector<Boolean_term>& result, Absorption_budget* budget = nullptr)
{
  result.clear();
  if(a.empty() || b.empty())
    return true;
  std::vector<Boolean_term> sorted_b = b;
  std::sort(sorted_b.begin(), sorted_b.end(), literal_count_less);
  std::vector<Boolean_term> products;
  for(const Boolean_term& x : a)
  {
    std::size_t work = 1;
    const bool implied = is_absorbed_by_any(x, sorted_b, work);
    if(budget != nullptr && !budget->charge(work))
      return false;
    if(implied)
    {
      result.push_back(x);
      continue;
    }
    if(products.size() + b.size() > max_dnf_candidates)
      return false;
    for(const Boolean_term& y : b)
    {
      const Boolean_term t{x.pos | y.pos, x.neg | y.neg};
      if(!is_contradictory(t))
        products.push_back(t);
    }
  }
  if(products.empty())
    return result.size() <= max_dnf_terms;
  if(!absorb(products, max_dnf_terms, budget))
    return false;
  // Then the products absorbed by a term kept alone.
  std::sort(result.begin(), result.end(), literal_count_less);
  if(budget != nullptr && !budget->charge(products.size() * result.size()))
    return false;
  const std::size_t alone = result.size();
  for(const Boolean_term& t : products)
  {
    bool absorbed = false;
    const int count = popcount64(t.literals());
    for(std::size_t j = 0; j < alone && !absorbed; ++j)
    {
      if(popcount64(result[j].literals()) >= count)
        break;
      absorbed = absorbs(result[j], t);
    }
    if(!absorbed)
      result.push_back(t);
  }
  return result.size() <= max_dnf_terms;
}

// DNF of (a | b), both absorbed: a term can only be absorbed by a term of
// the other operand, so this is O(|a| |b|), not an absorption of the union.
inline bool dnf_or(const std::vector<Boolean_term>& a, const std::vector<Boolean_term>& b,
                   std::vector<Boolean_term>& result, Absorption_budget* budget = nullptr)
{
  // Plain scans, no sorting: usually one operand is the long accumulated
  // sum and the other a few terms.
  if(budget != nullptr && !budget->charge(2 * a.size() * b.size()))
    return false;
  std::vector<Boolean_term> b_kept; // the terms of b no term of a absorbs (or equals)
  for(const Boolean_term& y : b)
    if(std::none_of(a.begin(), a.end(), [&](const Boolean_term& x) { return absorbs(x, y); }))
      b_kept.push_back(y);
  result.clear();
  for(const Boolean_term& x : a)
    // absorbs(y, x) with y kept means y != x (equal terms were dropped from b)
    if(std::none_of(b_kept.begin(), b_kept.end(), [&](const Boolean_term& y) { return absorbs(y, x); }))
      result.push_back(x);
  result.insert(result.end(), b_kept.begin(), b_kept.end());
  return result.size() <= max_dnf_terms;
}

// DNF of !a by De Morgan: !(t1 | ... | tm) = AND_j (OR of the negated
// literals of t_j), multiplied out clause by clause with absorption after
// each step, the fewest-literal clauses first to keep intermediates small.
inline bool dnf_not(const std::vector<Boolean_term>& a, std::vector<Boolean_term>& result)
{
  std::vector<Boolean_term> sorted = a;
  std::sort(sorted.begin(), sorted.end(), [](const Boolean_term& x, const Boolean_term& y) {
    return popcount64(x.literals()) < popcount64(y.literals());
  });
  result.assign(1, Boolean_term()); // the empty product is true
  std::vector<Boolean_term> clause, next;
  for(const Boolean_term& t : sorted)
  {
    clause.clear();
    for(std::uint64_t bits = t.pos; bits != 0; bits &= bits - 1)
      clause.push_back(Boolean_term{0, bits & (~bits + 1)});
    for(std::uint64_t bits = t.neg; bits != 0; bits &= bits - 1)
      clause.push_back(Boolean_term{bits & (~bits + 1), 0});
    if(!dnf_and(result, clause, next))
      return false;
    result.swap(next);
    if(result.empty())
      return true;
  }
  return true;
}

// Completes an absorbed DNF into the Blake canonical form, the set of all
// prime implicants, by Tison's method: for each variable in turn add every
// consensus on that variable (x.P | !x.Q -> P.Q when P.Q is consistent),
// then absorb.  A consensus on x contains neither x nor !x, so one sweep per
// variable suffices (Tison 1967; Brown, "Boolean Reasoning", 1990, 3.9).
inline bool blake_canonical_form(std::vector<Boolean_term>& terms, Absorption_budget* budget = nullptr)
{
  if(!absorb(terms, max_dnf_terms, budget))
    return false;
  std::uint64_t both = 0, seen_pos = 0, seen_neg = 0;
  for(const Boolean_term& t : terms)
  {
    seen_pos |= t.pos;
    seen_neg |= t.neg;
  }
  both = seen_pos & seen_neg; // only variables occurring in both polarities have consensus
  std::vector<std::size_t> with_pos, with_neg;
  for(; both != 0; both &= both - 1)
  {
    const std::uint64_t bit = both & (~both + 1);
    with_pos.clear();
    with_neg.clear();
    for(std::size_t i = 0; i < terms.size(); ++i)
    {
      if(terms[i].pos & bit)
        with_pos.push_back(i);
      else if(terms[i].neg & bit)
        with_neg.push_back(i);
    }
    if(with_pos.empty() || with_neg.empty())
      continue; // absorption by an earlier consensus removed one polarity
    if(with_pos.size() > max_dnf_candidates / with_neg.size())
      return false;
    const std::size_t old_size = terms.size();
    for(std::size_t p : with_pos)
      for(std::size_t q : with_neg)
      {
        const Boolean_term c{(terms[p].pos | terms[q].pos) & ~bit,
                             (terms[p].neg | terms[q].neg) & ~bit};
        if(!is_contradictory(c)) // opposed on a second variable: no consensus
          terms.push_back(c);
      }
    if(terms.size() != old_size && !absorb(terms, max_dnf_terms, budget))
      return false;
  }
  sort_canonically(terms);
  return true;
}

inline std::string quote_for_message(const std::string& text)
{
  // The whole text is shown, even when long: a column number is only useful
  // next to the text it counts in.
  std::string out = "\"";
  for(char c : text)
  {
    const unsigned char u = static_cast<unsigned char>(c);
    if(u >= 0x20 && u < 0x7f)
      out += c;
    else
      out += ' '; // keeps columns aligned with the original text
  }
  return out + "\"";
}

inline std::string describe_character(char c)
{
  const unsigned char u = static_cast<unsigned char>(c);
  if(u >= 0x21 && u < 0x7f)
    return std::string("'") + c + "'";
  static const char hex[] = "0123456789abcdef";
  return std::string("byte 0x") + hex[u >> 4] + hex[u & 15];
}

inline bool is_identifier_start(char c)
{
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
}

inline bool is_identifier_char(char c) { return is_identifier_start(c) || (c >= '0' && c <= '9'); }

inline bool is_space(char c)
{
  return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v';
}

// What the parser hands to Boolean_expression.
struct Parsed_expression
{
  std::vector<Boolean_term> terms; // Blake canonical form, sorted
  std::size_t number_of_variables = 0;
  Variable_naming naming = Variable_naming::CAPITAL_LETTERS;
};

// Recursive descent over the grammar of the documentation, building a small
// tree first: negations are pushed to the leaves (De Morgan) during the DNF
// conversion, so that a negated sub-expression is never expanded in the
// positive polarity it does not need, and n-ary nodes keep long chains like
// "A | B | C | ..." flat (no recursion per operand).
class Expression_parser
{
public:
  // `names` == nullptr: automatic naming.
  Expression_parser(const std::string& text, const std::vector<std::string>* names)
    : m_text(text), m_names(names)
  {}

  Parsed_expression run()
  {
    tokenize();
    if(m_tokens.size() == 1)
      fail(0, "empty Boolean expression",
           "write a variable, a constant (0, 1, false, true) or an expression");
    const std::size_t root = parse_or(0);
    const Token& t = current();
    if(t.kind == Token_kind::CLOSE)
      fail(t.position, "unmatched ')'");
    if(t.kind != Token_kind::END)
      fail(t.position, "unexpected " + describe(t), "expected an operator (&, |, -) or the end");

    Parsed_expression result;
    result.terms = to_dnf(root, false, 0);
    if(!blake_canonical_form(result.terms, &m_budget))
    {
      if(m_budget.exhausted)
        too_much_work();
      throw Invalid_input_error("Boolean expression " + quote_for_message(m_text) +
                                " has more than " + std::to_string(max_dnf_terms) +
                                " prime implicants (the limit of Boolean_expression); simplify it");
    }
    if(m_names != nullptr)
    {
      result.number_of_variables = m_names->size();
      result.naming = Variable_naming::EXPLICIT_NAMES;
    }
    else
    {
      result.number_of_variables = m_variable_count;
      result.naming = m_auto_naming;
    }
    return result;
  }

private:
  enum class Token_kind { IDENTIFIER, CONSTANT, NOT, AND, OR, MINUS, OPEN, CLOSE, END };

  struct Token
  {
    Token_kind kind;
    std::size_t position;
    std::size_t length;
    bool value; // for CONSTANT
  };

  enum class Node_kind { VARIABLE, CONSTANT, NOT, AND, OR };

  struct Node
  {
    Node_kind kind;
    std::size_t position; // where the sub-expression starts, for messages
    std::size_t value;    // variable index, or constant 0/1
    std::vector<std::size_t> children;
  };

  [[noreturn]] void fail(std::size_t position, const std::string& problem,
                         const std::string& hint = std::string()) const
  {
    std::string message = problem + " at column " + std::to_string(position + 1) + " in " +
                          quote_for_message(m_text);
    if(!hint.empty())
      message += ": " + hint;
    throw Parse_error(message, position);
  }

  std::string describe(const Token& t) const
  {
    if(t.kind == Token_kind::END)
      return "end of expression";
    if(t.kind == Token_kind::IDENTIFIER)
      return "identifier '" + m_text.substr(t.position, t.length) + "'";
    return "'" + m_text.substr(t.position, t.length) + "'";
  }

  void tokenize()
  {
    std::size_t i = 0;
    const std::size_t n = m_text.size();
    while(i < n)
    {
      const char c = m_text[i];
      if(is_space(c))
      {
        ++i;
        continue;
      }
      Token t{Token_kind::END, i, 1, false};
      switch(c)
      {
      case '!':
      case '~': t.kind = Token_kind::NOT; break;
      case '&': t.kind = Token_kind::AND; break;
      case '|': t.kind = Token_kind::OR; break;
      case '-': t.kind = Token_kind::MINUS; break;
      case '(': t.kind = Token_kind::OPEN; break;
      case ')': t.kind = Token_kind::CLOSE; break;
      default:
        if(c >= '0' && c <= '9')
        {
          std::size_t j = i;
          while(j < n && is_identifier_char(m_text[j]))
            ++j;
          const std::string number = m_text.substr(i, j - i);
          if(number != "0" && number != "1")
            fail(i, "unexpected '" + number + "'", "the only numeric constants are 0 and 1");
          t.kind = Token_kind::CONSTANT;
          t.length = 1;
          t.value = (number == "1");
        }
        else if(is_identifier_start(c))
        {
          std::size_t j = i;
          while(j < n && is_identifier_char(m_text[j]))
            ++j;
          t.length = j - i;
          const std::string word = m_text.substr(i, t.length);
          if(word == "true" || word == "false")
          {
            t.kind = Token_kind::CONSTANT;
            t.value = (word == "true");
          }
          else
            t.kind = Token_kind::IDENTIFIER;
        }
        else
          fail(i, "unexpected character " + describe_character(c),
               "expected a variable, a constant or one of ! ~ & | - ( )");
      }
      m_tokens.push_back(t);
      i += t.length;
    }
    m_tokens.push_back(Token{Token_kind::END, n, 0, false});
  }

  const Token& current() const { return m_tokens[m_next]; }

  std::size_t add_node(Node_kind kind, std::size_t position, std::size_t value = 0)
  {
    m_nodes.push_back(Node{kind, position, value, {}});
    return m_nodes.size() - 1;
  }

  // expression := difference ('|' difference)*
  std::size_t parse_or(std::size_t depth)
  {
    const std::size_t position = current().position;
    const std::size_t first = parse_difference(depth);
    if(current().kind != Token_kind::OR)
      return first;
    std::vector<std::size_t> children{first};
    while(current().kind == Token_kind::OR)
    {
      ++m_next;
      children.push_back(parse_difference(depth));
    }
    const std::size_t node = add_node(Node_kind::OR, position);
    m_nodes[node].children = std::move(children);
    return node;
  }

  // difference := conjunction ('-' conjunction)*, left-associative:
  // a - b - c = (a & !b) & !c, kept as one flat conjunction.
  std::size_t parse_difference(std::size_t depth)
  {
    const std::size_t position = current().position;
    const std::size_t first = parse_and(depth);
    if(current().kind != Token_kind::MINUS)
      return first;
    std::vector<std::size_t> children{first};
    while(current().kind == Token_kind::MINUS)
    {
      const std::size_t minus_position = current().position;
      ++m_next;
      const std::size_t operand = parse_and(depth);
      const std::size_t negation = add_node(Node_kind::NOT, minus_position);
      m_nodes[negation].children.push_back(operand);
      children.push_back(negation);
    }
    const std::size_t node = add_node(Node_kind::AND, position);
    m_nodes[node].children = std::move(children);
    return node;
  }

  // conjunction := unary ('&' unary)*
  std::size_t parse_and(std::size_t depth)
  {
    const std::size_t position = current().position;
    const std::size_t first = parse_unary(depth);
    if(current().kind != Token_kind::AND)
      return first;
    std::vector<std::size_t> children{first};
    while(current().kind == Token_kind::AND)
    {
      ++m_next;
      children.push_back(parse_unary(depth));
    }
    const std::size_t node = add_node(Node_kind::AND, position);
    m_nodes[node].children = std::move(children);
    return node;
  }

  // unary := ('!' | '~')* primary; counted, not recursed, so "!!!!...A" is cheap.
  std::size_t parse_unary(std::size_t depth)
  {
    const std::size_t position = current().position;
    bool negated = false;
    while(current().kind == Token_kind::NOT)
    {
      negated = !negated;
      ++m_next;
    }
    const std::size_t operand = parse_primary(depth);
    if(!negated)
      return operand;
    const std::size_t node = add_node(Node_kind::NOT, position);
    m_nodes[node].children.push_back(operand);
    return node;
  }

  // primary := identifier | constant | '(' expression ')'
  std::size_t parse_primary(std::size_t depth)
  {
    const Token t = current();
    switch(t.kind)
    {
    case Token_kind::IDENTIFIER:
      ++m_next;
      return add_node(Node_kind::VARIABLE, t.position, resolve(t));
    case Token_kind::CONSTANT:
      ++m_next;
      return add_node(Node_kind::CONSTANT, t.position, t.value ? 1 : 0);
    case Token_kind::OPEN:
    {
      if(depth >= max_nesting_depth)
        fail(t.position, "parentheses nested deeper than " + std::to_string(max_nesting_depth) +
                             " levels");
      ++m_next;
      const std::size_t inner = parse_or(depth + 1);
      if(current().kind != Token_kind::CLOSE)
      {
        if(current().kind == Token_kind::END)
          fail(current().position, "missing ')'",
               "the '(' at column " + std::to_string(t.position + 1) + " is not closed");
        fail(current().position, "unexpected " + describe(current()),
             "expected an operator or the ')' closing the '(' at column " +
                 std::to_string(t.position + 1));
      }
      ++m_next;
      return inner;
    }
    default:
      fail(t.position, "unexpected " + describe(t), "expected a variable, a constant, '!' or '('");
    }
  }

  std::size_t resolve(const Token& t)
  {
    const std::string word = m_text.substr(t.position, t.length);
    if(m_names != nullptr)
    {
      for(std::size_t i = 0; i < m_names->size(); ++i)
        if((*m_names)[i] == word)
          return i;
      std::string known;
      for(std::size_t i = 0; i < m_names->size() && i < 16; ++i)
        known += (i == 0 ? "" : ", ") + (*m_names)[i];
      if(m_names->size() > 16)
        known += ", ...";
      fail(t.position, "unknown variable '" + word + "'",
           m_names->empty() ? std::string("no variable names were given")
                            : "the variables are " + known);
    }

    Variable_naming naming;
    std::size_t index = 0;
    if(word.size() == 1 && word[0] >= 'A' && word[0] <= 'Z')
    {
      naming = Variable_naming::CAPITAL_LETTERS;
      index = std::size_t(word[0] - 'A');
    }
    else if(word.size() >= 2 && word[0] == 'f' &&
            std::all_of(word.begin() + 1, word.end(), [](char c) { return c >= '0' && c <= '9'; }))
    {
      naming = Variable_naming::INDEXED_F;
      for(std::size_t i = 1; i < word.size(); ++i)
      {
        index = 10 * index + std::size_t(word[i] - '0');
        if(index >= max_expression_variables)
          fail(t.position, "variable index too large in '" + word + "'",
               "at most " + std::to_string(max_expression_variables) + " variables, f0 to f" +
                   std::to_string(max_expression_variables - 1));
      }
    }
    else
      fail(t.position, "unknown variable '" + word + "'",
           "without explicit names, variables are the single capital letters A to Z "
           "or f0 to f63");

    if(!m_have_identifier)
    {
      m_have_identifier = true;
      m_first_word = word;
      m_first_position = t.position;
      m_auto_naming = naming;
    }
    else if(naming != m_auto_naming)
      fail(t.position, "variable '" + word + "' mixes naming conventions with '" + m_first_word +
                           "' (column " + std::to_string(m_first_position + 1) + ")",
           "use either A to Z or f0 to f63 throughout, or give explicit names");
    m_variable_count = std::max(m_variable_count, index + 1);
    return index;
  }

  [[noreturn]] void too_much_work() const
  {
    throw Invalid_input_error("Boolean expression too complex: converting " + quote_for_message(m_text) +
                              " to disjunctive normal form takes more than " +
                              std::to_string(max_absorption_work) +
                              " term comparisons (the limit of Boolean_expression); factor it or shorten it");
  }

  [[noreturn]] void too_many_terms(std::size_t node) const
  {
    throw Invalid_input_error(
        "Boolean expression too complex: the disjunctive normal form of the sub-expression "
        "starting at column " + std::to_string(m_nodes[node].position + 1) + " of " +
        quote_for_message(m_text) + " would have more than " + std::to_string(max_dnf_terms) +
        " terms (the limit of Boolean_expression); factor it or use fewer alternatives");
  }

  // DNF of node (or of its negation), negations pushed to the leaves.
  std::vector<Boolean_term> to_dnf(std::size_t node, bool negated, std::size_t depth) const
  {
    const Node& n = m_nodes[node];
    std::vector<Boolean_term> result;
    switch(n.kind)
    {
    case Node_kind::VARIABLE:
    {
      const std::uint64_t bit = std::uint64_t(1) << n.value;
      result.push_back(negated ? Boolean_term{0, bit} : Boolean_term{bit, 0});
      return result;
    }
    case Node_kind::CONSTANT:
      if((n.value != 0) != negated)
        result.push_back(Boolean_term());
      return result;
    case Node_kind::NOT:
      return to_dnf(n.children.front(), !negated, depth + 1);
    case Node_kind::AND:
    case Node_kind::OR:
    {
      const bool product = (n.kind == Node_kind::AND) != negated; // De Morgan
      if(product)
        result.assign(1, Boolean_term());
      std::vector<Boolean_term> combined;
      for(std::size_t child : n.children)
      {
        const std::vector<Boolean_term> operand = to_dnf(child, negated, depth + 1);
        const bool ok = product ? dnf_and(result, operand, combined, &m_budget)
                                : dnf_or(result, operand, combined, &m_budget);
        if(!ok && m_budget.exhausted)
          too_much_work();
        if(!ok)
          too_many_terms(node);
        result.swap(combined);
        if(product && result.empty())
          break; // false & anything
      }
      return result;
    }
    }
    return result;
  }

  const std::string& m_text;
  const std::vector<std::string>* m_names;
  std::vector<Token> m_tokens;
  std::size_t m_next = 0;
  std::vector<Node> m_nodes;
  mutable Absorption_budget m_budget; // shared by every step of the conversion
  bool m_have_identifier = false; // the first one fixes the automatic naming convention
  std::string m_first_word;
  std::size_t m_first_position = 0;
  Variable_naming m_auto_naming = Variable_naming::CAPITAL_LETTERS;
  std::size_t m_variable_count = 0; // largest index seen + 1
};

} // namespace internal

/// \ingroup PkgBooleanIsosurfacing3Ref
///
/// A Boolean function of up to 64 variables, the one expression type shared
/// by Marching-Cubes CSG of N meshes and by TBISO.  Variable `i` is a region
/// (inside mesh `i`; for fields, `f_i < 0`); a *state* is a `std::uint64_t`
/// whose bit `i` is set when the point is inside variable `i`.
///
/// The expression is stored in *Blake canonical form*: the sorted set of all
/// its prime implicants.  This form is unique for a Boolean function, so
/// `operator==` is equivalence of functions, and it makes the cheap
/// term-by-term `partially_evaluate()` exact (see the documentation).
///
/// See doc/Boolean_isosurfacing_3/boolean_expression.md for the grammar,
/// the limits and the complexity of every operation.
class Boolean_expression
{
public:
  typedef Boolean_term Term;

  static constexpr std::size_t max_variables = internal::max_expression_variables;
  static constexpr std::size_t max_terms = internal::max_dnf_terms;
  static constexpr std::size_t max_truth_table_variables = internal::max_truth_table_variables;
  static constexpr std::size_t max_nesting_depth = internal::max_nesting_depth;

  /// The constant `false` over no variable.
  Boolean_expression() = default;

  /// The disjunction of `terms` over `number_of_variables` variables.
  /// Contradictory terms are dropped; the result is put in canonical form.
  /// \throws Invalid_input_error if `number_of_variables > 64`, if a term
  /// uses a variable `>= number_of_variables`, or if the canonical form has
  /// more than `max_terms` terms.
  Boolean_expression(std::size_t number_of_variables, std::vector<Term> terms)
    : m_number_of_variables(number_of_variables), m_naming(default_naming(number_of_variables))
  {
    check_number_of_variables(number_of_variables);
    const std::uint64_t allowed = internal::low_bits_mask(number_of_variables);
    for(std::size_t i = 0; i < terms.size(); ++i)
      if((terms[i].literals() & ~allowed) != 0)
        throw Invalid_input_error("term #" + std::to_string(i) + " uses variable " +
                                  std::to_string(internal::lowest_bit_index(terms[i].literals() & ~allowed)) +
                                  " but the expression has only " +
                                  std::to_string(number_of_variables) + " variables");
    m_terms = std::move(terms);
    if(!internal::blake_canonical_form(m_terms))
      throw_too_many_terms("the given disjunctive normal form");
    update_support();
  }

  /// \name Parsing
  /// @{

  /// Parses `text` with automatic naming: the variables are either all
  /// single capital letters (`A` = 0 ... `Z` = 25) or all `f<k>` (`f0` ...
  /// `f63`).  `number_of_variables()` is then the largest index used plus one.
  /// \throws Parse_error (with the 0-based position of the problem) on a syntax
  /// error, an unknown identifier or mixed naming conventions.
  /// \throws Invalid_input_error if the canonical form would exceed `max_terms`.
  static Boolean_expression parse(const std::string& text)
  {
    return Boolean_expression(internal::Expression_parser(text, nullptr).run(), {});
  }

  /// Parses `text` where `names[i]` is the name of variable `i`.  Names are
  /// identifiers (`[A-Za-z_][A-Za-z0-9_]*`, not `true` or `false`), unique.
  /// `number_of_variables()` is `names.size()`.
  /// \throws Invalid_input_error on more than 64 names or an invalid or
  /// repeated name; otherwise as `parse(text)`.
  static Boolean_expression parse(const std::string& text, const std::vector<std::string>& names)
  {
    check_names(names);
    return Boolean_expression(internal::Expression_parser(text, &names).run(), names);
  }

  /// @}

  /// \name Factories (the seed's operations, generalised to `n` operands)
  /// @{

  /// `A | B | ...` over `n` variables (`false` for `n == 0`).
  static Boolean_expression union_of(std::size_t n)
  {
    check_number_of_variables(n);
    std::vector<Term> terms;
    for(std::size_t i = 0; i < n; ++i)
      terms.push_back(Term{std::uint64_t(1) << i, 0});
    return Boolean_expression(n, std::move(terms));
  }

  /// `A & B & ...` over `n` variables (`true` for `n == 0`).
  static Boolean_expression intersection_of(std::size_t n)
  {
    check_number_of_variables(n);
    return Boolean_expression(n, std::vector<Term>(1, Term{internal::low_bits_mask(n), 0}));
  }

  /// `A & !B` over 2 variables (the seed's DIFFERENCE).
  static Boolean_expression difference()
  {
    return Boolean_expression(2, std::vector<Term>(1, Term{1, 2}));
  }

  /// Variable `i` alone, over `n` variables.
  static Boolean_expression single(std::size_t i, std::size_t n)
  {
    check_number_of_variables(n);
    if(i >= n)
      throw Invalid_input_error("variable " + std::to_string(i) + " does not exist in an expression of " +
                                std::to_string(n) + " variables");
    return Boolean_expression(n, std::vector<Term>(1, Term{std::uint64_t(1) << i, 0}));
  }

  /// The constant `value` over `n` variables.
  static Boolean_expression constant(bool value, std::size_t n = 0)
  {
    check_number_of_variables(n);
    return Boolean_expression(n, value ? std::vector<Term>(1, Term()) : std::vector<Term>());
  }

  /// @}

  /// \name Access
  /// @{

  /// The number N of variables (meshes or fields).
  std::size_t number_of_variables() const { return m_number_of_variables; }

  /// The prime implicants, in canonical order.
  const std::vector<Term>& terms() const { return m_terms; }
  /// The number of prime implicants.
  std::size_t number_of_terms() const { return m_terms.size(); }

  /// true iff the function is constant false (no term).
  bool is_false() const { return m_terms.empty(); }
  /// true iff the function is constant true (one empty term).
  bool is_true() const { return m_terms.size() == 1 && m_terms.front().literals() == 0; }

  /// The mask of the variables the function actually depends on.
  std::uint64_t support() const { return m_support; }

  /// true iff flipping variable `i` changes the value somewhere: iff the
  /// regularized set can have a boundary face on variable `i`'s surface.
  bool depends_on(std::size_t i) const { return i < 64 && ((m_support >> i) & 1) != 0; }

  /// How `to_string()` names the variables.
  Variable_naming naming() const { return m_naming; }

  /// The name `to_string()` uses for variable `i`.
  std::string variable_name(std::size_t i) const
  {
    if(m_naming == Variable_naming::EXPLICIT_NAMES && i < m_names.size())
      return m_names[i];
    if(m_naming == Variable_naming::CAPITAL_LETTERS && i < 26)
      return std::string(1, char('A' + i));
    return "f" + std::to_string(i);
  }

  /// @}

  /// \name Evaluation (hot paths: no allocation)
  /// @{

  /// Value at `state` (bit `i` set = inside variable `i`; bits `>= number_of_variables()` ignored).
  /// O(number_of_terms()); for many evaluations with few variables prefer `truth_table()`.
  bool evaluate(std::uint64_t state) const
  {
    for(const Term& t : m_terms)
      if((state & (t.pos | t.neg)) == t.pos)
        return true;
    return false;
  }

  /// Value when only the variables in `known` are known, with values
  /// `state & known` (e.g. the fields whose sign is constant over a cell).
  /// Exact: `ALWAYS_TRUE` / `ALWAYS_FALSE` iff the function restricted to
  /// the known values is constant.  O(number_of_terms()).
  Expression_value partially_evaluate(std::uint64_t known, std::uint64_t state) const
  {
    bool undecided = false;
    for(const Term& t : m_terms)
    {
      const std::uint64_t literals = t.pos | t.neg;
      if(((state ^ t.pos) & literals & known) != 0)
        continue; // a known variable falsifies the term
      if((literals & ~known) == 0)
        return Expression_value::ALWAYS_TRUE;
      undecided = true;
    }
    return undecided ? Expression_value::UNDECIDED : Expression_value::ALWAYS_FALSE;
  }

  /// As `partially_evaluate(known, state)`, and writes to `undecided_terms`
  /// the indices (into `terms()`) of the terms that are neither falsified nor
  /// satisfied by the known variables: the only terms a cell has to look at.
  /// The indices written are complete only when `UNDECIDED` is returned.
  template <typename OutputIterator>
  Expression_value partially_evaluate(std::uint64_t known, std::uint64_t state,
                                      OutputIterator undecided_terms) const
  {
    bool undecided = false;
    for(std::size_t i = 0; i < m_terms.size(); ++i)
    {
      const std::uint64_t literals = m_terms[i].pos | m_terms[i].neg;
      if(((state ^ m_terms[i].pos) & literals & known) != 0)
        continue;
      if((literals & ~known) == 0)
        return Expression_value::ALWAYS_TRUE;
      undecided = true;
      *undecided_terms++ = i;
    }
    return undecided ? Expression_value::UNDECIDED : Expression_value::ALWAYS_FALSE;
  }

  /// The function with the variables of `known` fixed to `state & known`, in
  /// canonical form, over the same variables (the fixed ones no longer occur).
  /// Allocates; O(T^2) for T terms in the worst case.
  Boolean_expression restrict(std::uint64_t known, std::uint64_t state) const
  {
    Boolean_expression result = with_terms({});
    for(const Term& t : m_terms)
    {
      const std::uint64_t literals = t.pos | t.neg;
      if(((state ^ t.pos) & literals & known) != 0)
        continue;
      result.m_terms.push_back(Term{t.pos & ~known, t.neg & ~known});
    }
    // Restricting a complete set of prime implicants leaves a set that still
    // contains every prime implicant of the restriction (each prime p of f|x
    // comes from the prime x.p or p of f): absorption alone restores the
    // canonical form, no consensus step is needed.
    internal::absorb(result.m_terms);
    internal::sort_canonically(result.m_terms);
    result.update_support();
    return result;
  }

  /// The truth table: entry `s` is `evaluate(s)`, for all `2^number_of_variables()` states.
  /// Worth it when evaluating far more than `2^n` times with more than a few
  /// terms (Marching Cubes over N meshes: one lookup per lattice point).
  /// \throws Invalid_input_error if `number_of_variables() > max_truth_table_variables`.
  std::vector<bool> truth_table() const
  {
    if(m_number_of_variables > max_truth_table_variables)
      throw Invalid_input_error("truth table of " + std::to_string(m_number_of_variables) +
                                " variables requested; at most " +
                                std::to_string(max_truth_table_variables) +
                                " are supported (use evaluate() instead)");
    const std::uint64_t all = internal::low_bits_mask(m_number_of_variables);
    std::vector<bool> table(std::size_t(all) + 1, false);
    // Enumerate the states satisfying each term (the submasks of its free
    // variables): cheaper than evaluating every state when terms are long.
    for(const Term& t : m_terms)
    {
      const std::uint64_t free = all & ~t.literals();
      std::uint64_t sub = free;
      for(;;)
      {
        table[std::size_t(t.pos | sub)] = true;
        if(sub == 0)
          break;
        sub = (sub - 1) & free;
      }
    }
    return table;
  }

  /// @}

  /// \name Boundary structure (for TBISO)
  /// @{

  /// The Boolean difference dE/dx_i = E|x_i=1 XOR E|x_i=0, in canonical form.
  /// A point on the zero set of field `i` (and on no other) is on the
  /// boundary of the regularized set iff the derivative is true at the
  /// state of the other variables there: the derivative is the exact
  /// "which terms can share a face on variable i" table of the seed.
  /// \throws Invalid_input_error if `i >= number_of_variables()` or the result exceeds `max_terms`.
  Boolean_expression derivative(std::size_t i) const
  {
    if(i >= m_number_of_variables)
      throw Invalid_input_error("derivative with respect to variable " + std::to_string(i) +
                                " of an expression of " + std::to_string(m_number_of_variables) +
                                " variables");
    if(!depends_on(i))
      return with_terms({});
    const std::uint64_t bit = std::uint64_t(1) << i;
    const std::vector<Term> when_inside = restrict(bit, bit).m_terms;
    const std::vector<Term> when_outside = restrict(bit, 0).m_terms;
    std::vector<Term> result;
    if(!exclusive_or(when_inside, when_outside, result))
      throw_too_many_terms("the derivative with respect to " + variable_name(i));
    return with_terms(std::move(result));
  }

  /// @}

  /// \name Combination
  /// Variables are matched by index; the result has as many variables as the
  /// larger operand and takes its naming (the left one's on a tie).
  /// \throws Invalid_input_error if the canonical form of the result exceeds `max_terms`.
  /// @{

  friend Boolean_expression operator!(const Boolean_expression& a)
  {
    std::vector<Term> result;
    if(!internal::dnf_not(a.m_terms, result) || !internal::blake_canonical_form(result))
      throw_too_many_terms("the complement");
    return a.with_terms(std::move(result));
  }

  friend Boolean_expression operator&(const Boolean_expression& a, const Boolean_expression& b)
  {
    std::vector<Term> result;
    if(!internal::dnf_and(a.m_terms, b.m_terms, result) || !internal::blake_canonical_form(result))
      throw_too_many_terms("the intersection");
    return wider(a, b).with_terms(std::move(result));
  }

  friend Boolean_expression operator|(const Boolean_expression& a, const Boolean_expression& b)
  {
    std::vector<Term> result;
    if(!internal::dnf_or(a.m_terms, b.m_terms, result) || !internal::blake_canonical_form(result))
      throw_too_many_terms("the union");
    return wider(a, b).with_terms(std::move(result));
  }

  /// `a & !b`.
  friend Boolean_expression operator-(const Boolean_expression& a, const Boolean_expression& b)
  {
    std::vector<Term> not_b, result;
    if(!internal::dnf_not(b.m_terms, not_b) || !internal::dnf_and(a.m_terms, not_b, result) ||
       !internal::blake_canonical_form(result))
      throw_too_many_terms("the difference");
    return wider(a, b).with_terms(std::move(result));
  }

  /// @}

  /// The canonical form as text: terms joined by `" | "`, literals by
  /// `" & "`, negation `!`, constants `false` and `true`.  Parsing it back
  /// (with the same names, for `EXPLICIT_NAMES`) gives an equal expression.
  std::string to_string() const
  {
    if(is_false())
      return "false";
    if(is_true())
      return "true";
    std::string out;
    for(std::size_t k = 0; k < m_terms.size(); ++k)
    {
      if(k != 0)
        out += " | ";
      const Term& t = m_terms[k];
      bool first = true;
      for(std::uint64_t bits = t.literals(); bits != 0; bits &= bits - 1)
      {
        const int v = internal::lowest_bit_index(bits);
        if(!first)
          out += " & ";
        first = false;
        if((t.neg >> v) & 1)
          out += '!';
        out += variable_name(std::size_t(v));
      }
    }
    return out;
  }

  /// Equality of the Boolean functions (the canonical form is unique);
  /// `number_of_variables()` and the names are not compared.
  friend bool operator==(const Boolean_expression& a, const Boolean_expression& b)
  {
    return a.m_terms == b.m_terms;
  }
  friend bool operator!=(const Boolean_expression& a, const Boolean_expression& b) { return !(a == b); }

  friend std::ostream& operator<<(std::ostream& os, const Boolean_expression& e)
  {
    return os << e.to_string();
  }

private:
  Boolean_expression(internal::Parsed_expression&& parsed, const std::vector<std::string>& names)
    : m_terms(std::move(parsed.terms)), m_number_of_variables(parsed.number_of_variables),
      m_naming(parsed.naming), m_names(names)
  {
    update_support();
  }

  static Variable_naming default_naming(std::size_t n)
  {
    return n <= 26 ? Variable_naming::CAPITAL_LETTERS : Variable_naming::INDEXED_F;
  }

  static void check_number_of_variables(std::size_t n)
  {
    if(n > max_variables)
      throw Invalid_input_error("a Boolean expression has at most " + std::to_string(max_variables) +
                                " variables, " + std::to_string(n) + " requested");
  }

  static void check_names(const std::vector<std::string>& names)
  {
    if(names.size() > max_variables)
      throw Invalid_input_error("a Boolean expression has at most " + std::to_string(max_variables) +
                                " variables, " + std::to_string(names.size()) + " names given");
    for(std::size_t i = 0; i < names.size(); ++i)
    {
      const std::string& name = names[i];
      const bool valid = !name.empty() && internal::is_identifier_start(name[0]) &&
                         std::all_of(name.begin(), name.end(), internal::is_identifier_char) &&
                         name != "true" && name != "false";
      if(!valid)
        throw Invalid_input_error("variable name #" + std::to_string(i) + " \"" + name +
                                  "\" is not an identifier ([A-Za-z_][A-Za-z0-9_]*, "
                                  "not true or false)");
      for(std::size_t j = 0; j < i; ++j)
        if(names[j] == name)
          throw Invalid_input_error("variable name \"" + name + "\" is given twice (#" +
                                    std::to_string(j) + " and #" + std::to_string(i) + ")");
    }
  }

  [[noreturn]] static void throw_too_many_terms(const std::string& what)
  {
    throw Invalid_input_error("Boolean expression too complex: " + what +
                              " would have more than " + std::to_string(max_terms) +
                              " terms in canonical form (the limit of Boolean_expression)");
  }

  static const Boolean_expression& wider(const Boolean_expression& a, const Boolean_expression& b)
  {
    return b.m_number_of_variables > a.m_number_of_variables ? b : a;
  }

  // A copy of this expression's variables and naming with canonical `terms`.
  Boolean_expression with_terms(std::vector<Term> terms) const
  {
    Boolean_expression result;
    result.m_terms = std::move(terms);
    result.m_number_of_variables = m_number_of_variables;
    result.m_naming = m_naming;
    result.m_names = m_names;
    result.update_support();
    return result;
  }

  static bool exclusive_or(const std::vector<Term>& a, const std::vector<Term>& b,
                           std::vector<Term>& result)
  {
    std::vector<Term> not_a, not_b, a_only, b_only;
    return internal::dnf_not(a, not_a) && internal::dnf_not(b, not_b) &&
           internal::dnf_and(a, not_b, a_only) && internal::dnf_and(b, not_a, b_only) &&
           internal::dnf_or(a_only, b_only, result) && internal::blake_canonical_form(result);
  }

  void update_support()
  {
    m_support = 0;
    for(const Term& t : m_terms)
      m_support |= t.literals();
  }

  std::vector<Term> m_terms; // Blake canonical form, canonical order
  std::uint64_t m_support = 0;
  std::size_t m_number_of_variables = 0;
  Variable_naming m_naming = Variable_naming::CAPITAL_LETTERS;
  std::vector<std::string> m_names; // only for EXPLICIT_NAMES
};

} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_BOOLEAN_EXPRESSION_H
