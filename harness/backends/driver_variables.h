#pragma once
// Mesa's variables that choose a driver or change it (GALLIUM_DRIVER,
// LP_NATIVE_VECTOR_WIDTH). A backend named for such a driver sets them for
// itself (BackendEntry::environment); Mesa reads some of them once per
// driver library, so where several backends share a process (`snell
// bench`), one made later may come up on a variable another set. Its
// refusal then names that backend instead of telling the user to unset a
// variable they never set.
#include <string>

namespace snell {

// Sets `name` in this process for `backend`'s driver, and remembers who.
void setDriverVariable(const std::string& backend, const std::string& name,
                       const std::string& value);
// The backend that set `name` in this process, or "" (the user's, or unset).
std::string driverVariableSetBy(const std::string& name);

// Why `backend`, which runs `driver` at its native vector width, cannot
// run on `renderer` with LP_NATIVE_VECTOR_WIDTH=`width` (set by the user,
// or by the backend `setBy`); `alternative` is the backend for that width,
// if there is one.
std::string whyNotAtNativeVectorWidth(const std::string& backend, const std::string& driver,
                                      const std::string& renderer, const std::string& width,
                                      const std::string& setBy, const std::string& alternative);

}  // namespace snell
