// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// The JSON output of the measured_parameterization program (--json), the one serializer of
// both documents: a failed run, and a successful run. The sections from the library's report
// of the parameterization are templates that read the report (`Parameterizer::Report`,
// instantiated by run.cpp); the other sections read plain data (json_output.cpp). No CGAL
// here.

#ifndef MBP_CLI_JSON_OUTPUT_H
#define MBP_CLI_JSON_OUTPUT_H

#include "run.h"
#include "summary.h"
#include "text_output.h"

#include <cstddef>
#include <string>

namespace mbp_cli {

/// the document of a failed run, {"error": MESSAGE, "code": STATUS, "error_code": N}: STATUS is
/// the exit status (1: the input cannot be parameterized or an output cannot be written; 2: a
/// command-line error), N the library's `Error_code` when the failure is one (null otherwise,
/// `error_code` 0)
std::string json_failure(const std::string& message, int status, int error_code);

/// the members from the command line: input, generated_mesh, mesh, output, svg, solver,
/// center_locator, border_distance
void write_command_line(Json_writer& j, const Run_facts& f);
/// the members on the mesh and its layout: vertices, faces, isolated_vertices, seams,
/// seam_edges, automatic_seams, uvs, border, center
void write_mesh(Json_writer& j, const Run_facts& f);
/// the times measured by the program: io_times
void write_io_times(Json_writer& j, const Run_facts& f);
/// the distortion: quality
void write_quality(Json_writer& j, const Quality& q);

/// the layouts tried and the one kept: border_choice
template <class Parameterizer>
void write_border_choice(Json_writer& j, const typename Parameterizer::Report& r, const Run_facts& f)
{
  j.begin_object("border_choice").member("mode", border_name(f.options.border));
  if(r.chosen_candidate >= 0)
  {
    const typename Parameterizer::Border_candidate& c = r.border_candidates[static_cast<std::size_t>(r.chosen_candidate)];
    j.begin_object("chosen")
       .member("index", r.chosen_candidate)
       .member("kind", candidate_kind<Parameterizer>(c, f.options.distance))
       .member("blend", c.blend)
       .member("mean_value_interior", c.mean_value_interior)
       .member("angle_distortion", c.objective)
       .end_object();
  }
  else
    j.null_member("chosen");
  j.begin_array("candidates", false);
  for(const typename Parameterizer::Border_candidate& c : r.border_candidates)
    j.begin_object()
       .member("kind", candidate_kind<Parameterizer>(c, f.options.distance))
       .member("blend", c.blend)
       .member("mean_value_interior", c.mean_value_interior)
       .member("valid", c.valid)
       .member("angle_distortion", c.objective)  // null when not valid
       .end_object();
  j.end_array();
  j.end_object();
}

/// the stages of the parameterization: times
template <class Report>
void write_times(Json_writer& j, const Report& r)
{
  j.begin_object("times")
     .member("preparation", r.preparation_seconds)
     .member("center", r.center_seconds)
     .member("distances", r.distance_seconds)
     .member("border_map", r.border_map_seconds)
     .member("conformal_border", r.conformal_border_seconds)
     .member("interior", r.interior_seconds)  // every layout tried before repair
     .member("output", r.output_seconds)
     .member("total", r.total_seconds)
     .end_object();
}

/// the repair (`enabled`: not --no-repair): repair
template <class Report>
void write_repair(Json_writer& j, const Report& r, bool enabled)
{
  j.begin_object("repair")
     .member("enabled", enabled)
     .member("flipped_faces_before", r.flipped_faces_before_repair)
     .member("repaired", r.repaired)
     .member("blend", r.blend)
     .member("interior", r.mean_value_interior ? "mean value coordinates" : "discrete conformal")
     .member("candidates", r.repair_candidates)
     .member("seconds", r.repair_seconds)
     .end_object();
}

/// the solver's work: statistics
template <class Report>
void write_statistics(Json_writer& j, const Report& r)
{
  j.begin_object("statistics")
     .member("factorizations", r.statistics.factorizations)
     .member("back_substitutions", r.statistics.back_substitutions)
     .member("factorization_seconds", r.statistics.factorization_seconds)
     .member("back_substitution_seconds", r.statistics.back_substitution_seconds)
     .end_object();
}

/// the document of a successful run
template <class Parameterizer>
std::string json_document(const typename Parameterizer::Report& r, const Run_facts& f)
{
  Json_writer j;
  j.begin_object();
  write_command_line(j, f);
  write_border_choice<Parameterizer>(j, r, f);
  write_mesh(j, f);
  write_times(j, r);
  write_io_times(j, f);
  write_repair(j, r, f.options.repair);
  write_statistics(j, r);
  write_quality(j, f.result.quality);
  j.end_object();
  return j.text();
}

} // namespace mbp_cli

#endif // MBP_CLI_JSON_OUTPUT_H
