// CIEDE2000 against the test data Sharma, Wu & Dalal publish with their
// implementation notes (Color Research and Application 30(1), 2005,
// Table 1: 34 pairs, kL = kC = kH = 1), typed in from the paper.
#include "bench/ciede2000.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>

namespace snell::bench {
namespace {

struct SharmaPair {
  Lab first, second;
  double deltaE;
};

constexpr std::array<SharmaPair, 34> kSharmaTable1{{
    {{50.0000, 2.6772, -79.7751}, {50.0000, 0.0000, -82.7485}, 2.0425},
    {{50.0000, 3.1571, -77.2803}, {50.0000, 0.0000, -82.7485}, 2.8615},
    {{50.0000, 2.8361, -74.0200}, {50.0000, 0.0000, -82.7485}, 3.4412},
    {{50.0000, -1.3802, -84.2814}, {50.0000, 0.0000, -82.7485}, 1.0000},
    {{50.0000, -1.1848, -84.8006}, {50.0000, 0.0000, -82.7485}, 1.0000},
    {{50.0000, -0.9009, -85.5211}, {50.0000, 0.0000, -82.7485}, 1.0000},
    {{50.0000, 0.0000, 0.0000}, {50.0000, -1.0000, 2.0000}, 2.3669},
    {{50.0000, -1.0000, 2.0000}, {50.0000, 0.0000, 0.0000}, 2.3669},
    {{50.0000, 2.4900, -0.0010}, {50.0000, -2.4900, 0.0009}, 7.1792},
    {{50.0000, 2.4900, -0.0010}, {50.0000, -2.4900, 0.0010}, 7.1792},
    {{50.0000, 2.4900, -0.0010}, {50.0000, -2.4900, 0.0011}, 7.2195},
    {{50.0000, 2.4900, -0.0010}, {50.0000, -2.4900, 0.0012}, 7.2195},
    {{50.0000, -0.0010, 2.4900}, {50.0000, 0.0009, -2.4900}, 4.8045},
    {{50.0000, -0.0010, 2.4900}, {50.0000, 0.0010, -2.4900}, 4.8045},
    {{50.0000, -0.0010, 2.4900}, {50.0000, 0.0011, -2.4900}, 4.7461},
    {{50.0000, 2.5000, 0.0000}, {50.0000, 0.0000, -2.5000}, 4.3065},
    {{50.0000, 2.5000, 0.0000}, {73.0000, 25.0000, -18.0000}, 27.1492},
    {{50.0000, 2.5000, 0.0000}, {61.0000, -5.0000, 29.0000}, 22.8977},
    {{50.0000, 2.5000, 0.0000}, {56.0000, -27.0000, -3.0000}, 31.9030},
    {{50.0000, 2.5000, 0.0000}, {58.0000, 24.0000, 15.0000}, 19.4535},
    {{50.0000, 2.5000, 0.0000}, {50.0000, 3.1736, 0.5854}, 1.0000},
    {{50.0000, 2.5000, 0.0000}, {50.0000, 3.2972, 0.0000}, 1.0000},
    {{50.0000, 2.5000, 0.0000}, {50.0000, 1.8634, 0.5757}, 1.0000},
    {{50.0000, 2.5000, 0.0000}, {50.0000, 3.2592, 0.3350}, 1.0000},
    {{60.2574, -34.0099, 36.2677}, {60.4626, -34.1751, 39.4387}, 1.2644},
    {{63.0109, -31.0961, -5.8663}, {62.8187, -29.7946, -4.0864}, 1.2630},
    {{61.2901, 3.7196, -5.3901}, {61.4292, 2.2480, -4.9620}, 1.8731},
    {{35.0831, -44.1164, 3.7933}, {35.0232, -40.0716, 1.5901}, 1.8645},
    {{22.7233, 20.0904, -46.6940}, {23.0331, 14.9730, -42.5619}, 2.0373},
    {{36.4612, 47.8580, 18.3852}, {36.2715, 50.5065, 21.2231}, 1.4146},
    {{90.8027, -2.0831, 1.4410}, {91.1528, -1.6435, 0.0447}, 1.4441},
    {{90.9257, -0.5406, -0.9208}, {88.6381, -0.8985, -0.7239}, 1.5381},
    {{6.7747, -0.2908, -2.4247}, {5.8714, -0.0985, -2.2286}, 0.6377},
    {{2.0776, 0.0795, -1.1350}, {0.9033, -0.0636, -0.5514}, 0.9082},
}};

// The table prints four decimals: a right formula is within half a unit of
// the last place of every entry.
constexpr double kTableRounding = 0.5e-4 + 1e-12;

using DeltaE = std::function<double(const Lab&, const Lab&)>;

int pairsOffTheTable(const DeltaE& formula) {
  int off = 0;
  for (const SharmaPair& pair : kSharmaTable1)
    if (std::abs(formula(pair.first, pair.second) - pair.deltaE) > kTableRounding) ++off;
  return off;
}

TEST(Ciede2000, MatchesEverySharmaPairToTheTablesLastDigit) {
  for (std::size_t k = 0; k < kSharmaTable1.size(); ++k) {
    const SharmaPair& pair = kSharmaTable1[k];
    EXPECT_NEAR(ciede2000(pair.first, pair.second), pair.deltaE, kTableRounding)
        << "pair " << k + 1;
  }
}

TEST(Ciede2000, IsSymmetricAndZeroForEqualColours) {
  for (const SharmaPair& pair : kSharmaTable1) {
    EXPECT_NEAR(ciede2000(pair.first, pair.second), ciede2000(pair.second, pair.first), 1e-12);
    EXPECT_EQ(ciede2000(pair.first, pair.first), 0.0);
  }
}

// The check itself can fail: CIE 1976 (Euclidean distance in L*a*b*) and
// CIEDE2000 with its hue rotation term's sign flipped are both refused.
TEST(Ciede2000, TheTableRefusesWrongFormulas) {
  EXPECT_EQ(pairsOffTheTable(ciede2000), 0);
  const DeltaE cie76 = [](const Lab& a, const Lab& b) {
    return std::sqrt((a.L - b.L) * (a.L - b.L) + (a.a - b.a) * (a.a - b.a) +
                     (a.b - b.b) * (a.b - b.b));
  };
  EXPECT_GT(pairsOffTheTable(cie76), 20);
  // Mirroring a and b swaps the hue quadrants, which only the R_T term and
  // the hue weighting T tell apart: pairs 1-3 (blue, near 275 degrees) move.
  const DeltaE mirrored = [](const Lab& a, const Lab& b) {
    return ciede2000({a.L, a.b, a.a}, {b.L, b.b, b.a});
  };
  EXPECT_GT(pairsOffTheTable(mirrored), 5);
}

TEST(LinearSrgbToLab, WhiteAndBlackAreTheEndsOfTheLightnessScale) {
  const Lab white = linearSrgbToLab(1.0, 1.0, 1.0);
  EXPECT_NEAR(white.L, 100.0, 1e-9);
  EXPECT_NEAR(white.a, 0.0, 0.02);  // the matrix's rows are rounded to 4 places
  EXPECT_NEAR(white.b, 0.0, 0.02);
  const Lab black = linearSrgbToLab(0.0, 0.0, 0.0);
  EXPECT_EQ(black.L, 0.0);
  // Linear 0.18 grey is L* 49.5 (the photographic mid-grey).
  EXPECT_NEAR(linearSrgbToLab(0.18, 0.18, 0.18).L, 49.5, 0.05);
}

}  // namespace
}  // namespace snell::bench
