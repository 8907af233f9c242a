// tbiso's extraction: in core (the whole fields in memory) or out of core
// (the fields read or evaluated slab by slab, the surface streamed to a PLY
// file), with the library's progress (its `callback` named parameter) drawn
// by cli.h's Tool::progress() on a terminal.

#ifndef BISO_TOOLS_TBISO_EXTRACT_H
#define BISO_TOOLS_TBISO_EXTRACT_H

#include "tbiso_input.h"

#include <CGAL/Boolean_isosurfacing_3/IO/Boolean_isosurface_PLY_stream.h>
#include <CGAL/Boolean_isosurfacing_3/boolean_isosurface.h>
#include <CGAL/Boolean_isosurfacing_3/boolean_isosurface_by_slabs.h>

#include <cstdio>
#include <functional>
#include <string>

namespace tbiso_tool {

typedef BI::Boolean_isosurface_soup<Point> Soup;

typedef std::function<bool(double)> Callback;

template <typename Domain>
BI::Boolean_isosurface_statistics extract(const Domain& domain, const BI::Scalar_fields& fields,
                                          const BI::Boolean_expression& expression, Soup& soup, const Options& o,
                                          const Callback& progress)
{
  // slab_layers 0: the library's default.
  const auto np =
      BI::parameters::close_at_domain_boundary(o.close, BI::parameters::slab_layers(o.slab_layers)).callback(progress);
  if(o.parallel)
    return BI::extract_boolean_isosurface<CGAL::Parallel_if_available_tag>(domain, fields, expression, soup, np);
  return BI::extract_boolean_isosurface<CGAL::Sequential_tag>(domain, fields, expression, soup, np);
}

inline std::size_t out_of_core_slab_layers(const Options& o) { return o.slab_layers ? o.slab_layers : 8; }

// The fields of `source` (a ScalarFieldSource) slab by slab, the surface
// streamed to o.output.
template <typename Source>
BI::Boolean_isosurface_slab_statistics extract_out_of_core(const Grid& grid, Source& source,
                                                           const BI::Boolean_expression& expression, const Options& o,
                                                           const Callback& progress)
{
  BI::IO::Boolean_isosurface_PLY_stream ply(o.output);
  const auto np = BI::parameters::close_at_domain_boundary(
                      o.close, BI::parameters::slab_layers(out_of_core_slab_layers(o)))
                      .callback(progress);
  const BI::Boolean_isosurface_slab_statistics s =
      o.parallel
          ? BI::extract_boolean_isosurface_by_slabs<CGAL::Parallel_if_available_tag>(grid, source, expression, ply, np)
          : BI::extract_boolean_isosurface_by_slabs<CGAL::Sequential_tag>(grid, source, expression, ply, np);
  ply.close();
  return s;
}

} // namespace tbiso_tool

#endif // BISO_TOOLS_TBISO_EXTRACT_H
