#pragma once
/// \file xml_escape.hpp
/// Escapes text for an XML attribute value or element content (& < > " '), for the VTU and PVD writers.

#include <string>

namespace symcontact {

std::string xml_escape(const std::string& s);

}  // namespace symcontact
