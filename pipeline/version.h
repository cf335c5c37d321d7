#pragma once
namespace tessref {
const char* version();
}  // namespace tessref
