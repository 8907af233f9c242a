// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

// libFuzzer harness of Boolean_expression::parse().  The input is the
// expression text; BISO_FUZZ_NAMING selects the style the seeds use and the
// printing checked by the round trip: CAPITAL_LETTERS (A, B, ...) or
// INDEXED_F (f0, f1, ...).  Automatic naming reads both, so each harness also
// reaches the mixed-style errors.  A parsed expression must print and parse
// back to the same function, and its operators must agree with evaluate().

#include "fuzz_common.h"

#include <CGAL/Boolean_isosurfacing_3/Boolean_expression.h>

#include <string>

#ifndef BISO_FUZZ_NAMING
#  define BISO_FUZZ_NAMING CAPITAL_LETTERS
#endif

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  using CGAL::Boolean_isosurfacing::Boolean_expression;
  const std::string text(reinterpret_cast<const char*>(data), size);
  Boolean_expression e;
  try
  {
    e = Boolean_expression::parse(text);
  }
  catch(const CGAL::Boolean_isosurfacing::Invalid_input_error&)
  {
    return 0;
  }
  const std::string printed = e.to_string();
  Boolean_expression again;
  try
  {
    again = Boolean_expression::parse(printed);
  }
  catch(const CGAL::Boolean_isosurfacing::Invalid_input_error&)
  {
    biso_fuzz::require(false, "the printed expression does not parse");
  }
  // Printing drops variables the function does not depend on, so compare
  // the functions, not the variable counts.
  biso_fuzz::require(again.terms() == e.terms(), "parse(to_string(e)) differs from e");
  if(e.naming() == CGAL::Boolean_isosurfacing::Variable_naming::BISO_FUZZ_NAMING)
    biso_fuzz::require(again.naming() == e.naming() || e.support() == 0, "naming lost in the round trip");
  // Operators against evaluation, on a few states.
  try
  {
    const Boolean_expression n = !e;
    for(std::uint64_t s : {std::uint64_t(0), ~std::uint64_t(0), std::uint64_t(0x5555555555555555),
                           std::uint64_t(size * 0x9e3779b97f4a7c15ull)})
      biso_fuzz::require(n.evaluate(s) != e.evaluate(s), "!e agrees with e");
  }
  catch(const CGAL::Boolean_isosurfacing::Invalid_input_error&)
  {
    // the complement can exceed max_terms: a reported limit, not a finding
  }
  return 0;
}
