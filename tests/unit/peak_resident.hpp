#pragma once
// The budget tests' measure of memory: the most this process has had
// resident since the test last reset it, in MiB. getrusage's ru_maxrss is
// the peak of the whole process, so a test that runs after a hungrier one
// (the whole vkt_unit_tests binary in one process, rather than ctest's one
// test a process) could not see its own peak, and its check would pass or
// fail by what ran before it. Linux resets the peak, VmHWM in
// /proc/self/status, to what is resident now when 5 is written to
// /proc/self/clear_refs. Not measured in the Windows build
// (scripts/windows-build.sh), where only the messages are checked: 0.
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>

namespace vkt_test {

// Starts a new peak; false where the kernel does not allow it.
inline bool reset_peak_resident() {
#ifndef _WIN32
    std::ofstream clear("/proc/self/clear_refs");
    clear << "5";
    clear.flush();
    return bool(clear);
#else
    return true;
#endif
}

// The peak since the last reset_peak_resident(), MiB.
inline double peak_resident_mib() {
#ifndef _WIN32
    std::ifstream status("/proc/self/status");
    for (std::string line; std::getline(status, line);)
        if (line.rfind("VmHWM:", 0) == 0) return std::atof(line.c_str() + 6) / 1024.0;  // kB
#endif
    return 0.0;
}

}  // namespace vkt_test
