// snell_adversary_soak --seconds N --seed S: the adversarial machine against
// the oracle until the time is up, built-ins, catalog listings and the
// derived programs of the catalog's captures in turn, under both
// APIs' rules. Prints the evaluations and escapes; an escape
// comes with its inputs, the machine's seed and, for reflect and refract, a
// `snell eval` line that shows the oracle's intervals. Exit code 1 when
// something escaped, 2 for a usage error.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

#include "adversary/adversary_check.h"
#include "adversary/adversary_inputs.h"

namespace {

int usage(const char* message) {
  std::fprintf(stderr,
               "snell_adversary_soak: %s\nusage: snell_adversary_soak --seconds N --seed S\n",
               message);
  return 2;
}

bool parseNumber(const char* text, unsigned long long& value) {
  char* end = nullptr;
  value = std::strtoull(text, &end, 0);
  return end && *end == '\0' && end != text;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace snell::adversary;
  unsigned long long seconds = 60, seed = 1;
  for (int k = 1; k < argc; ++k) {
    const std::string arg = argv[k];
    if ((arg == "--seconds" || arg == "--seed") && k + 1 < argc) {
      unsigned long long& target = arg == "--seconds" ? seconds : seed;
      if (!parseNumber(argv[++k], target))
        return usage(("not a number: " + std::string(argv[k])).c_str());
    } else {
      return usage(("unknown argument: " + arg).c_str());
    }
  }
  try {
    const auto start = std::chrono::steady_clock::now();
    const auto elapsed = [&] {
      return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
    Rng rng(seed);
    Tally builtins, listings, derivedPrograms;
    double nextReport = 30;
    std::size_t shownBuiltins = 0, shownListings = 0, shownDerived = 0;
    const auto& catalog = catalogListings();
    const auto& derivedCatalog = derivedCatalogListings();
    if (catalog.empty() || derivedCatalog.empty()) {
      std::fprintf(stderr, "snell_adversary_soak: the catalog (shaders/) has no listings\n");
      return 2;
    }
    for (std::uint64_t round = 0; elapsed() < static_cast<double>(seconds); ++round) {
      const snell::PrecisionRules rules =
          round % 2 ? snell::PrecisionRules::Vulkan : snell::PrecisionRules::Glsl;
      for (Formula f : kAllFormulas)
        for (int input = 0; input < 50; ++input)
          checkFormula(f, formulaInputs(f, rng), rules, 8, rng.next(), builtins);
      const ListingInputs& listing = catalog[round % catalog.size()];
      checkListing(sampleVertices(listing, 16, rng), rules, 6, rng.next(), listings);
      const DerivedListingInputs& derived = derivedCatalog[round % derivedCatalog.size()];
      const DerivedListingInputs sampled{derived.source, derived.outputs,
                                         sampleVertices(derived.bindings, 16, rng),
                                         derived.handWritten};
      checkDerivedListing(sampled, rules, 6, rng.next(), derivedPrograms);
      checkHandWrittenAgainstDerived(sampled, rules, 6, rng.next(), derivedPrograms);
      // Escapes as they are found, so that a long run shows them early.
      for (Tally* t : {&builtins, &listings, &derivedPrograms})
        for (std::size_t& shown = t == &builtins   ? shownBuiltins
                                  : t == &listings ? shownListings
                                                   : shownDerived;
             shown < t->firstEscapes.size(); ++shown)
          std::printf("ESCAPE %s\n", t->firstEscapes[shown].c_str());
      if (elapsed() >= nextReport) {
        std::printf("%.0f s: %llu evaluations, %llu escapes\n", elapsed(),
                    static_cast<unsigned long long>(builtins.evaluations + listings.evaluations +
                                                    derivedPrograms.evaluations),
                    static_cast<unsigned long long>(builtins.escapes + listings.escapes +
                                                    derivedPrograms.escapes));
        std::fflush(stdout);
        nextReport += 30;
      }
    }
    Tally all = builtins;
    all.add(listings);
    all.add(derivedPrograms);
    std::printf(
        "seed %llu, %.0f s: %llu evaluations (%llu built-in, %llu listing, %llu derived program), "
        "%llu escapes\n",
        seed, elapsed(), static_cast<unsigned long long>(all.evaluations),
        static_cast<unsigned long long>(builtins.evaluations),
        static_cast<unsigned long long>(listings.evaluations),
        static_cast<unsigned long long>(derivedPrograms.evaluations),
        static_cast<unsigned long long>(all.escapes));
    return all.escapes ? 1 : 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "snell_adversary_soak: %s\n", e.what());
    return 2;
  }
}
