#include "symcontact/core/error.hpp"

namespace symcontact {

namespace {
std::string compose(const std::string& file, const std::string& key, const std::string& message) {
  std::string s;
  if (!file.empty()) s += file + ": ";
  if (!key.empty()) s += key + ": ";
  return s + message;
}
}  // namespace

InputError::InputError(std::string file, std::string key, const std::string& message)
    : std::runtime_error(compose(file, key, message)),
      file_(std::move(file)),
      key_(std::move(key)),
      message_(message) {}

InputError InputError::in_file(const std::string& file) const { return InputError(file, key_, message_); }

}  // namespace symcontact
