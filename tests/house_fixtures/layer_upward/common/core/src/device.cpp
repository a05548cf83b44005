#include "vkt/frame/runner.hpp"  // core must not know the runner
