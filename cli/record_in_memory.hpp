#pragma once
// Tracing into memory for the commands that replay at once (explain, step): the inputs and
// filters of `trace`, without the file in between.
#include "cli/fill_flags.hpp"
#include "cli/model_flags.hpp"
#include "cli/trace_flags.hpp"
#include "trace/trace.hpp"

namespace scantrace::cli {

// The event budget of a trace held in memory unless --max-events says otherwise: a pixel-level
// trace of a large scene must not exhaust memory, and a replay could not show that many steps.
inline constexpr long long kInMemoryMaxEvents = 2'000'000;

// Traces the input `what` names with the fill and model options, as `trace` would write it. A
// selection that matches nothing is an error (selection_check.hpp); a trace cut by the budget is
// returned with truncated() set, for the caller to say what that means for its output.
trace::Trace record_in_memory(const TraceFlags& what, const FillFlags& fill,
                              const ModelFlags& model);

}  // namespace scantrace::cli
