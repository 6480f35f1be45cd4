// SPDX-License-Identifier: GPL-3.0-or-later
// embind adapter: small free functions converting between JS values and the core API. No
// algorithm lives here. Results cross the boundary as plain JS objects (JSON text parsed on the
// JS side of this call), and every C++ exception becomes a real JS Error carrying the core's
// message and a `code` ("bad-input", "too-large", "unsupported", "internal").
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <string>

#include "desia/check.h"
#include "desia/document.h"
#include "desia/error.h"
#include "desia/version.h"

namespace {

using emscripten::val;

val parseJsonText(const std::string& text) { return val::global("JSON").call<val>("parse", val(text)); }

// Runs `operation` and converts any exception into a thrown JS Error. The JS throw happens after
// the catch block has ended, so C++ destructors and exception cleanup have run (toolchain.md #8).
template <typename Operation>
val guarded(Operation&& operation) {
  std::string message, code;
  try {
    return operation();
  } catch (const desia::Error& e) {
    message = e.what();
    code = desia::errorCodeName(e.code());
  } catch (const std::bad_alloc&) {
    message = "out of memory";
    code = "too-large";
  } catch (const std::exception& e) {
    message = std::string("internal error: ") + e.what();
    code = "internal";
  } catch (...) {
    message = "internal error: unknown exception";
    code = "internal";
  }
  val error = val::global("Error").new_(val(message));
  error.set("code", val(code));
  error.set("name", val(std::string("DesiaError")));
  error.throw_();
}

val check(const std::string& text, const std::string& method, const std::string& source) {
  return guarded([&] {
    desia::CheckOptions options;
    options.method = desia::parseCheckMethod(method);
    const desia::AssemblyDocument document = desia::parseAssemblyText(text, source);
    return parseJsonText(desia::checkReportToJson(document, desia::checkAssembly(document, options), -1));
  });
}

val parseDocument(const std::string& text, const std::string& source) {
  return guarded([&] { return parseJsonText(desia::documentToJson(desia::parseAssemblyText(text, source), -1)); });
}

std::string version() { return desia::kVersion; }

}  // namespace

EMSCRIPTEN_BINDINGS(desia) {
  emscripten::function("check", &check);
  emscripten::function("parseDocument", &parseDocument);
  emscripten::function("version", &version);
}
