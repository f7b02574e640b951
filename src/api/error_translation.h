#pragma once
#include <new>
#include <string>

#include "candela/error.h"
#include "io/load_diagnostics.h"

namespace candela::api {

// Runs `work` and turns what the layers below throw into Error with the line `candela` prints for it (after
// "candela: "): their one-line messages as they are, and a failed allocation as the command's "not enough memory
// for the <command> command".
template <class Work>
auto withErrorsTranslated(const char* command, Work&& work) {
  try {
    return work();
  } catch (const Error&) {
    throw;
  } catch (const std::bad_alloc&) {
    throw Error(std::string("not enough memory for the ") + command + " command");
  } catch (const std::exception& e) {
    throw Error(printableText(e.what()));
  }
}

}  // namespace candela::api
