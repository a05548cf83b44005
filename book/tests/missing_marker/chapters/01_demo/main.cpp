// A fixture for book/tests: it has one marker, [hello], but the page asks
// for [no-such-marker].
#include <cstdio>

int main() {
    // [hello]
    std::puts("hello");
    // [/hello]
}
