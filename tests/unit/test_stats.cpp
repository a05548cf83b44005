#include "vkt/frame/stats.hpp"

#include <catch2/catch_test_macros.hpp>

TEST_CASE("summaries of hand-checked samples", "[stats]") {
    vkt::Summary s = vkt::summarize({5, 1, 4, 2, 3});
    CHECK(s.min == 1);
    CHECK(s.median == 3);
    CHECK(s.p95 == 5);  // nearest rank: ceil(0.95 * 5) = 5th value
    CHECK(s.max == 5);

    s = vkt::summarize({4, 1, 3, 2});
    CHECK(s.median == 2.5);

    std::vector<double> hundred;
    for (int i = 100; i >= 1; --i) hundred.push_back(i);
    s = vkt::summarize(hundred);
    CHECK(s.median == 50.5);
    CHECK(s.p95 == 95);  // ceil(0.95 * 100) = 95th value
    CHECK(s.min == 1);
    CHECK(s.max == 100);
}

TEST_CASE("summaries print as the JSON --benchmark promises", "[stats]") {
    CHECK(vkt::json_summary({4, 1, 3, 2}) ==
          R"({"min": 1.0000, "median": 2.5000, "p95": 4.0000, "max": 4.0000})");
    CHECK(vkt::json_summary({}) == "null");
}

TEST_CASE("JSON strings are quoted and escaped", "[stats]") {
    CHECK(vkt::json_string("llvmpipe (LLVM 15)") == R"j("llvmpipe (LLVM 15)")j");
    CHECK(vkt::json_string(R"j(a "b" \c)j") == R"j("a \"b\" \\c")j");
    CHECK(vkt::json_string("tab\there") == R"j("tab\u0009here")j");
}

TEST_CASE("one value and no values", "[stats]") {
    vkt::Summary one = vkt::summarize({7});
    CHECK(one.min == 7);
    CHECK(one.median == 7);
    CHECK(one.p95 == 7);
    CHECK(one.max == 7);
    vkt::Summary none = vkt::summarize({});
    CHECK(none.max == 0);
}
