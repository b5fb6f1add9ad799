#include <cstdio>
#include <cstdlib>

#include "framework/context.hpp"
#include "framework/error.hpp"
#include "test_support.hpp"

namespace fw::test {

bool backend_required(const std::string& backend) {
    const char* req = std::getenv("LAB_REQUIRE_BACKENDS");
    if (!req) return false;
    const std::string list = std::string(",") + req + ",";
    if (list.find("," + backend + ",") != std::string::npos) return true;
    if (list.find(",built,") == std::string::npos) return false;
    try {
        return backend_compiled_in(parse_backend(backend));
    } catch (const UsageError&) {
        return false;
    }
}

void skip_part_without(const std::string& backend, const std::string& what,
                       const std::string& why) {
    if (backend_required(backend)) {
        FAIL_CHECK("backend " << backend << " is required (LAB_REQUIRE_BACKENDS="
                              << std::getenv("LAB_REQUIRE_BACKENDS") << ") but: " << why);
        return;
    }
    std::printf("SKIP %s (backend %s): %s\n", what.c_str(), backend.c_str(), why.c_str());
    std::fflush(stdout);
}

}  // namespace fw::test
