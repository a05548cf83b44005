// A fixture for the book tests (book/CMakeLists.txt): it has one marker, [hello], but the page asks
// for [no-such-marker].
#include <cstdio>

int main() {
    // [hello]
    std::puts("hello");
    // [/hello]
}
