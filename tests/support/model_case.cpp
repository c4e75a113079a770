#include "support/model_case.hpp"

#include <sstream>

#include "symcontact/model/problem_reader.hpp"

namespace symcontact::testing {

std::unique_ptr<ModelCase> build_model(const std::string& text, const std::filesystem::path& folder) {
  auto c = std::make_unique<ModelCase>();
  c->spec = parse_problem(text, "case.toml", folder.string());
  std::ostringstream quiet;
  const Logger log(quiet, Verbosity::kQuiet);
  PhaseTimes times;
  c->model = Model::build(c->spec, log, times);
  return c;
}

}  // namespace symcontact::testing
