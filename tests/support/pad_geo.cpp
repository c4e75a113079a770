#include "support/pad_geo.hpp"

#include <sstream>

namespace symcontact::testing {

std::string pad_geo_2d(double mesh_size) {
  const double corners[4][2] = {{-0.5, 0.0}, {0.5, 0.0}, {0.5, 0.25}, {-0.5, 0.25}};
  std::ostringstream s;
  for (int k = 0; k < 4; ++k) {
    s << "Point(" << k + 1 << ") = {" << corners[k][0] << ", " << corners[k][1] << ", 0";
    if (mesh_size > 0.0) s << ", " << mesh_size;
    s << "};\n";
  }
  s << "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};\n"
       "Curve Loop(1) = {1, 2, 3, 4};\nPlane Surface(1) = {1};\n"
       "Physical Surface(\"solid\") = {1};\nPhysical Curve(\"bottom\") = {1};\nPhysical Curve(\"top\") = {3};\n";
  return s.str();
}

}  // namespace symcontact::testing
