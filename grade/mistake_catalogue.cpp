#include "grade/mistake_catalogue.hpp"

#include <stdexcept>

#include <nlohmann/json.hpp>

namespace scantrace::grade {
namespace {

const nlohmann::json& document() {
  static const nlohmann::json doc = nlohmann::json::parse(mistake_catalogue_json());
  return doc;
}

}  // namespace

const std::vector<CatalogueMistake>& mistake_catalogue() {
  static const std::vector<CatalogueMistake> all = [] {
    std::vector<CatalogueMistake> out;
    for (const auto& m : document().at("mistakes"))
      out.push_back({m.at("id"), m.at("sentence"), m.at("fix"), m.value("verdict", "")});
    return out;
  }();
  return all;
}

const CatalogueMistake& catalogue_mistake(std::string_view id) {
  for (const auto& m : mistake_catalogue())
    if (m.id == id) return m;
  throw std::out_of_range("the mistake catalogue has no id '" + std::string(id) + "'");
}

double whole_image_tolerance(std::string_view name) {
  const auto& w = document().at("whole_image");
  const auto it = w.find(std::string(name));
  if (it == w.end() || !it->is_number())
    throw std::out_of_range("the mistake catalogue has no whole-image tolerance '" +
                            std::string(name) + "'");
  return it->get<double>();
}

}  // namespace scantrace::grade
