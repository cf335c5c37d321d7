#pragma once
// One GL context shared by every test in the binary; tests skip with the reason when the
// machine cannot create one.
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "glref/gl_context.h"

namespace tessref::glref::testing {

// Null when no context could be made; reason() says why.
GlContext* shared_context();
const std::string& context_failure();

}  // namespace tessref::glref::testing

#define TESSREF_REQUIRE_GL(ctx)                                                            \
  ::tessref::glref::GlContext* ctx = ::tessref::glref::testing::shared_context();          \
  if (!ctx) GTEST_SKIP() << "no GL 4.5 context: " << ::tessref::glref::testing::context_failure()
