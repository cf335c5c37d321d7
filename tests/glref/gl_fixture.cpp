#include "gl_fixture.h"

#include "glref/gl_error.h"

namespace tessref::glref::testing {
namespace {
struct Shared {
  std::unique_ptr<GlContext> context;
  std::string failure;
  Shared() {
    try {
      context = std::make_unique<GlContext>();
    } catch (const std::exception& e) {
      failure = e.what();
    }
  }
};
Shared& shared() {
  static Shared s;
  return s;
}
}  // namespace

GlContext* shared_context() { return shared().context.get(); }
const std::string& context_failure() { return shared().failure; }

}  // namespace tessref::glref::testing
