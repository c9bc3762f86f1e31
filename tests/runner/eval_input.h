#pragma once
// `snell eval` input of every shape the command reads, for the streaming
// tests: widths 1 to 4, reflect and refract, rays near the critical angle
// (two ways), non-finite components, lines only nlohmann reads (extra keys,
// "nan" strings, odd spacing), physics lines, blank and malformed lines.
#include <fmt/format.h>

#include <cmath>
#include <string>

namespace snell::testing {

inline std::string evalLineOfEveryShape(int k) {
  const double a = 0.013 * k;
  const double x = std::sin(a), y = -std::cos(a);
  const double eta = (k % 5 == 0) ? 1.0 / std::sqrt(1.0 - y * y) : 0.6 + 0.01 * (k % 100);
  switch (k % 13) {
    case 0:
      return fmt::format("{{\"fn\":\"refract\",\"I\":[{},{},0],\"N\":[0,1,0],\"eta\":{}}}", x, y,
                         eta);
    case 1:
      return fmt::format("{{\"fn\":\"reflect\",\"I\":[{},{}],\"N\":[0,1]}}", x, y);
    case 2:
      return fmt::format("{{\"fn\":\"refract\",\"I\":[{}],\"N\":[1],\"eta\":{}}}", y, eta);
    case 3:
      return fmt::format("{{\"fn\":\"refract\",\"I\":[{},{},0.1,-0],\"N\":[0,1,0,0],\"eta\":{}}}",
                         x, y, eta);
    case 4:
      return fmt::format(
          " {{ \"eta\" : {} , \"N\" : [ 0 , 1 , 0 ] , \"I\" : [ {} , {} , 0 ] , "
          "\"fn\" : \"refract\" }} \r",
          eta, x, y);
    case 5:
      return fmt::format("{{\"fn\":\"refract\",\"I\":[\"nan\",{},0],\"N\":[0,1,0],\"eta\":{}}}", y,
                         eta);
    case 6:
      return fmt::format("{{\"fn\":\"reflect\",\"I\":[1e39,{},\"-inf\"],\"N\":[0,1,0],\"id\":{}}}",
                         y, k);
    case 7:
      return fmt::format(
          "{{\"fn\":\"fresnel\",\"model\":\"exact\",\"cos_i\":{},\"n1\":1,\"n2\":1.5}}",
          std::abs(y));
    case 8:
      return k % 2 ? "" : "   \t";
    case 9:
      return k % 3 ? "{\"fn\":\"refract\",\"I\":[1,0,0],\"N\":[0,1,0]}"
                   : "{\"fn\":\"refract\",\"I\":[";
    case 10:
      return fmt::format(
          "{{\"fn\":\"refract\",\"I\":[{:.3e},{:.3e},0],\"N\":[0,1E0,0],\"eta\":{}}}", x, y, eta);
    case 11:
      return fmt::format("{{\"fn\":\"reflect\",\"I\":[{},{},0.5,0],\"N\":[0,1,0,0],\"eta\":\"x\"}}",
                         x, y);
    default:
      return fmt::format("{{\"fn\":\"refract\",\"I\":[{},{},0],\"N\":[0,1,0],\"eta\":{}}}", x, y,
                         1.0 / eta);
  }
}

inline std::string evalInputOfEveryShape(int lines) {
  std::string text;
  for (int k = 0; k < lines; ++k) text += evalLineOfEveryShape(k) + "\n";
  return text;
}

}  // namespace snell::testing
