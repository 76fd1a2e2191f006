#include "cli/record_in_memory.hpp"

#include <type_traits>
#include <variant>

#include "cli/selection_check.hpp"
#include "io/obj_loader.hpp"
#include "trace/record.hpp"

namespace scantrace::cli {

trace::Trace record_in_memory(const TraceFlags& what, const FillFlags& fill,
                              const ModelFlags& model) {
  FillOptions options = model.apply(fill.options(), is_obj_file(what.scene));
  options.winding_rule = what.winding_rule();
  const auto input = trace_input(what, model, options.shading, fill.clamp_colors);
  trace::TraceFilter filter = what.filter();
  check_selection(input, filter, what.input_name());
  if (!filter.max_events) filter.max_events = kInMemoryMaxEvents;
  return std::visit(
      [&](const auto& in) {
        using Input = std::decay_t<decltype(in)>;
        if constexpr (std::is_same_v<Input, Scene>)
          return trace::record_scene(in, options, filter);
        else if constexpr (std::is_same_v<Input, trace::GeneralPolygonInput>)
          return trace::record_polygon(in, options, filter);
        else
          return trace::record_triangle(in, options, filter);
      },
      input);
}

}  // namespace scantrace::cli
