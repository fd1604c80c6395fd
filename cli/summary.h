// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// The one-line summary of a run, and the texts that name the border kept and the repair (also
// in the OBJ header and the SVG caption). The templates read the library's report of the
// parameterization (`Parameterizer::Report`, instantiated by run.cpp); the rest reads plain
// data (summary.cpp). No CGAL here.

#ifndef MBP_CLI_SUMMARY_H
#define MBP_CLI_SUMMARY_H

#include "run.h"
#include "text_output.h"

#include <cstddef>
#include <string>

namespace mbp_cli {

/// what the summary says before the border kept: the mesh, the seams, the border and the center
std::string summary_of_mesh(const Run_facts& facts);
/// what the summary says after the solver: the distortion
std::string summary_of_quality(const Quality& quality);

/// the kind of a layout tried: circle, conformal, or measured:<distance>
template <class Parameterizer>
std::string candidate_kind(const typename Parameterizer::Border_candidate& c, const std::string& distance)
{
  return c.family == Parameterizer::CIRCLE      ? std::string("circle")
         : c.family == Parameterizer::CONFORMAL ? std::string("conformal")
                                                : "measured:" + distance;
}

/// the layout kept: "conformal (3 layouts tried)", "measured:poisson t 0.38, mean value
/// interior (9 layouts tried)"
template <class Parameterizer>
std::string kept_border(const typename Parameterizer::Report& report, const std::string& distance)
{
  const std::size_t n = report.border_candidates.size();
  const std::string tried = " (" + std::to_string(n) + (n == 1 ? " layout" : " layouts") + " tried)";
  if(report.chosen_candidate < 0)
    return "none valid" + tried;
  const typename Parameterizer::Border_candidate& c =
    report.border_candidates[static_cast<std::size_t>(report.chosen_candidate)];
  const std::string kind = candidate_kind<Parameterizer>(c, distance);
  return kind + (kind == "circle" || c.blend == 0. ? std::string() : " t " + rounded(c.blend, 3)) +
         (c.mean_value_interior ? ", mean value interior" : "") + tried;
}

/// whether the layout was repaired: "repaired 12 flipped faces: blend 0.25, mean value
/// interior", "no repair needed" or "repair off"
template <class Report>
std::string repair_text(const Report& report, bool enabled)
{
  if(report.repaired)
    return "repaired " + std::to_string(report.flipped_faces_before_repair) + " flipped faces: blend " +
           rounded(report.blend, 3) + (report.mean_value_interior ? ", mean value interior" : "");
  return enabled ? "no repair needed" : "repair off";
}

/// the one-line summary of a successful run
template <class Parameterizer>
std::string summary_line(const typename Parameterizer::Report& r, const Run_facts& f)
{
  const Options& o = f.options;
  return summary_of_mesh(f) + " | border " + border_name(o.border) + ": " +
         kept_border<Parameterizer>(r, o.distance) + " | seconds: preparation " +
         rounded(r.preparation_seconds, 3) + ", center " + rounded(r.center_seconds, 3) + ", distances " +
         rounded(r.distance_seconds, 3) + ", border map " + rounded(r.border_map_seconds, 3) +
         ", conformal border " + rounded(r.conformal_border_seconds, 3) + ", layouts " +
         rounded(r.interior_seconds, 3) + ", total " + rounded(r.total_seconds, 3) + " | " +
         solver_name(o.solver) + ": " + std::to_string(r.statistics.factorizations) + " factorizations, " +
         std::to_string(r.statistics.back_substitutions) + " back-substitutions" +
         summary_of_quality(f.result.quality) + " | " + repair_text(r, o.repair) + " | wrote " + o.output +
         (o.svg.empty() ? std::string() : ", " + o.svg) + "\n";
}

} // namespace mbp_cli

#endif // MBP_CLI_SUMMARY_H
