#pragma once
// JSON form of the trace events (format v1). Written with nlohmann::ordered_json so that `type`
// comes first on every line and keys keep a fixed, documented order — part of what makes two runs
// produce identical bytes.
#include <nlohmann/json.hpp>

#include "events.hpp"

namespace scantrace {
void to_json(nlohmann::ordered_json& j, const Vec2& p);
void from_json(const nlohmann::json& j, Vec2& p);
void to_json(nlohmann::ordered_json& j, const Color& c);
void from_json(const nlohmann::json& j, Color& c);
}  // namespace scantrace

namespace scantrace::trace {

nlohmann::ordered_json event_to_json(const Event& e);

// Throws nlohmann::json::exception (missing key, wrong type) or std::invalid_argument (unknown
// type) with a message that names the problem; the reader adds the line number.
Event event_from_json(const nlohmann::json& j);

}  // namespace scantrace::trace
