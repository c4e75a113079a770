#pragma once
/// \file model_case.hpp
/// A problem file's model for tests of the stages after the reader: the ProblemSpec parsed from a snippet
/// and the Model built from it (the model refers to the spec, so both are kept together), quietly.

#include <filesystem>
#include <memory>
#include <string>

#include "symcontact/model/model.hpp"

namespace symcontact::testing {

struct ModelCase {
  ProblemSpec spec;
  std::unique_ptr<Model> model;
};

/// Parses `text` as "case.toml" with its mesh paths relative to `folder`, and builds the model. Throws the
/// reader's and the model's InputError.
std::unique_ptr<ModelCase> build_model(const std::string& text, const std::filesystem::path& folder);

}  // namespace symcontact::testing
