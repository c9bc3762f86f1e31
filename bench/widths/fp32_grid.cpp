#include "widths/fp32_grid.h"

#include <cmath>
#include <limits>

namespace snell::widths {
namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
}

double floatDown(double x) {
  if (std::isnan(x) || std::isinf(x)) return x;
  if (x > kMaxFloat) return kMaxFloat;
  if (x < -kMaxFloat) return -kInf;
  float f = static_cast<float>(x);
  if (static_cast<double>(f) > x) f = std::nextafter(f, -std::numeric_limits<float>::infinity());
  return f;
}

double floatUp(double x) { return -floatDown(-x); }

double ulpOf(double x) {
  const double a = std::fabs(x);
  if (a < kMinNormal) return 0x1p-149;
  if (a > kMaxFloat) return 0x1p104;
  int exponent = 0;
  const double mantissa =
      std::frexp(a, &exponent);  // a = mantissa * 2^exponent, mantissa in [0.5, 1)
  const double gapAbove = std::ldexp(1.0, exponent - 24);
  return mantissa == 0.5 ? gapAbove / 2 : gapAbove;
}

float roundTo(double head, double tail, Rounding mode) {
  const double value = head + tail;  // for the sign and the direction only
  double below = floatDown(head);
  if (below == head && tail < 0) below = floatDown(std::nextafter(head, -kInf));
  const bool exact = below == head && tail == 0;
  if (exact) return static_cast<float>(below);
  const double above = floatUp(std::nextafter(below, kInf));
  switch (mode) {
    case Rounding::Down:
      return static_cast<float>(below);
    case Rounding::Up:
      return static_cast<float>(above);
    case Rounding::TowardZero:
      return static_cast<float>(value > 0 ? below : above);
    case Rounding::Nearest:
      break;
  }
  const double toBelow = (head - below) + tail;
  const double toAbove = (above - head) - tail;
  return static_cast<float>(toBelow <= toAbove ? below : above);
}

double twoSum(double a, double b, double* error) {
  const double sum = a + b;
  const double bVirtual = sum - a;
  const double aVirtual = sum - bVirtual;
  *error = (a - aVirtual) + (b - bVirtual);
  return sum;
}

double twoProduct(double a, double b, double* error) {
  const double product = a * b;
  *error = std::fma(a, b, -product);
  return product;
}

double addDown(double a, double b) {
  double error = 0;
  const double sum = twoSum(a, b, &error);
  return error < 0 ? std::nextafter(sum, -kInf) : sum;
}
double addUp(double a, double b) { return -addDown(-a, -b); }
double mulDown(double a, double b) {
  double error = 0;
  const double product = twoProduct(a, b, &error);
  if (std::isnan(error)) return product;
  return error < 0 ? std::nextafter(product, -kInf) : product;
}
double mulUp(double a, double b) { return -mulDown(-a, b); }

double inUlps(double distance, double reference) { return distance / ulpOf(reference); }

}  // namespace snell::widths
