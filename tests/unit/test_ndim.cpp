// The n-dimensional mathematics of chapters 18-20 (vkt/domains/ndim.hpp): meshes,
// rotations, transforms and projection, against counts, lengths and points
// worked out by hand.
#include "vkt/domains/ndim.hpp"

#include <catch2/catch_approx.hpp>
#include <catch2/catch_test_macros.hpp>
#include <catch2/generators/catch_generators.hpp>

#include <bit>
#include <cmath>
#include <numbers>
#include <random>

using Catch::Approx;
namespace nd = vkt::ndim;

namespace {

constexpr float pi = std::numbers::pi_v<float>;

float distance(std::span<const float> a, std::span<const float> b) {
    float sum = 0.0f;
    for (size_t k = 0; k < a.size(); ++k) sum += (a[k] - b[k]) * (a[k] - b[k]);
    return std::sqrt(sum);
}

float length(std::span<const float> a) {
    float sum = 0.0f;
    for (float c : a) sum += c * c;
    return std::sqrt(sum);
}

// Angles drawn uniformly from [-pi, pi) with a fixed seed.
std::vector<float> random_angles(int n, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> angle(-pi, pi);
    std::vector<float> out(size_t(nd::plane_count(n)));
    for (float& a : out) a = angle(rng);
    return out;
}

nd::Transform random_transform(int n, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> any(-2.0f, 2.0f), positive(0.5f, 2.0f);
    nd::Transform t = nd::Transform::identity(n);
    for (float& p : t.position) p = any(rng);
    for (float& s : t.scale) s = positive(rng);
    t.angles = random_angles(n, seed + 1);
    return t;
}

}  // namespace

TEST_CASE("the n-cube has 2^n vertices and n 2^(n-1) edges", "[ndim]") {
    const auto [n, vertices, edges] = GENERATE(
        table<int, size_t, size_t>({{3, 8, 12}, {4, 16, 32}, {8, 256, 1024}, {12, 4096, 24576}}));
    const nd::Mesh cube = nd::make_cube(n, 1.0f);
    CHECK(cube.dim == n);
    CHECK(cube.vertex_count() == vertices);
    CHECK(cube.edges.size() == edges);
}

TEST_CASE("n-cube vertices are +-s by the bits of their index", "[ndim]") {
    const nd::Mesh cube = nd::make_cube(4, 0.5f);
    // Vertex 5 = 0b0101: bits 0 and 2 set.
    const auto v = cube.vertex(5);
    CHECK(v[0] == 0.5f);
    CHECK(v[1] == -0.5f);
    CHECK(v[2] == 0.5f);
    CHECK(v[3] == -0.5f);
    CHECK(cube.radius() == Approx(1.0f));  // sqrt(4 * 0.25)
}

TEST_CASE("every n-cube edge joins vertices one bit apart, has length 2s, and is grouped by axis",
          "[ndim]") {
    const int n = GENERATE(3, 4, 8, 12);
    const float s = 0.75f;
    const nd::Mesh cube = nd::make_cube(n, s);
    bool all_one_bit = true, all_length = true, all_grouped = true;
    for (size_t e = 0; e < cube.edges.size(); ++e) {
        const auto [a, b] = cube.edges[e];
        const uint32_t diff = a ^ b;
        all_one_bit = all_one_bit && std::popcount(diff) == 1;
        all_length =
            all_length && std::abs(distance(cube.vertex(a), cube.vertex(b)) - 2 * s) < 1e-5f;
        all_grouped = all_grouped && diff == (1u << nd::cube_edge_axis(n, e)) && a < b;
    }
    CHECK(all_one_bit);
    CHECK(all_length);
    CHECK(all_grouped);
}

TEST_CASE("the 24-cell: 24 vertices at radius s, 96 edges of length s", "[ndim]") {
    const float s = 1.5f;
    const nd::Mesh cell = nd::make_24_cell(s);
    CHECK(cell.dim == 4);
    REQUIRE(cell.vertex_count() == 24);
    CHECK(cell.edges.size() == 96);
    for (size_t i = 0; i < cell.vertex_count(); ++i) CHECK(length(cell.vertex(i)) == Approx(s));
    for (const auto [a, b] : cell.edges)
        CHECK(distance(cell.vertex(a), cell.vertex(b)) == Approx(s));
    // Each vertex meets 8 edges (96 * 2 / 24).
    std::vector<int> degree(24, 0);
    for (const auto [a, b] : cell.edges) ++degree[a], ++degree[b];
    for (int d : degree) CHECK(d == 8);
}

TEST_CASE("rotation planes are numbered in lexicographic order", "[ndim]") {
    CHECK(nd::plane_count(4) == 6);
    CHECK(nd::plane_count(12) == 66);
    CHECK(nd::plane_axes(4, 0) == std::pair{0, 1});
    CHECK(nd::plane_axes(4, 2) == std::pair{0, 3});
    CHECK(nd::plane_axes(4, 3) == std::pair{1, 2});
    CHECK(nd::plane_axes(4, 5) == std::pair{2, 3});
    for (int n : {2, 3, 5, 12})
        for (int p = 0; p < nd::plane_count(n); ++p) {
            const auto [i, j] = nd::plane_axes(n, p);
            CHECK(nd::plane_index(n, i, j) == p);
        }
}

TEST_CASE("rotations are orthogonal with determinant 1 and preserve length", "[ndim]") {
    const int n = GENERATE(2, 3, 4, 7, 12);
    const auto angles = random_angles(n, uint32_t(100 + n));
    const nd::Matrix r = nd::rotation_matrix(n, angles);
    // R^T R = I.
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            float dot = 0.0f;
            for (int k = 0; k < n; ++k) dot += r(k, i) * r(k, j);
            CHECK(dot == Approx(i == j ? 1.0f : 0.0f).margin(1e-5));
        }
    CHECK(nd::determinant(r) == Approx(1.0).epsilon(1e-5));
    std::vector<float> x(static_cast<size_t>(n)), y(static_cast<size_t>(n));
    for (int k = 0; k < n; ++k) x[size_t(k)] = float(k) - 1.5f;
    nd::Transform t = nd::Transform::identity(n);
    t.angles = angles;
    nd::transform_point(t, x, y);
    CHECK(length(y) == Approx(length(x)).epsilon(1e-5));
}

TEST_CASE("determinant of matrices worked by hand", "[ndim]") {
    nd::Matrix m(3);
    // [[2, 0, 1], [1, 3, 2], [1, 1, 1]]: 2(3 - 2) - 0 + 1(1 - 3) = 0.
    const float values[9] = {2, 0, 1, 1, 3, 2, 1, 1, 1};
    for (int i = 0; i < 9; ++i) m(i / 3, i % 3) = values[i];
    CHECK(nd::determinant(m) == Approx(0.0).margin(1e-9));
    m(2, 2) = 2;  // now 2(6 - 2) - 0 + 1(1 - 3) = 6
    CHECK(nd::determinant(m) == Approx(6.0));
    // A single swap of two axes: -1.
    nd::Matrix swap(2);
    swap(0, 1) = swap(1, 0) = 1;
    CHECK(nd::determinant(swap) == Approx(-1.0));
}

TEST_CASE("zero angles give the identity", "[ndim]") {
    const int n = GENERATE(3, 4, 12);
    const std::vector<float> zero(size_t(nd::plane_count(n)), 0.0f);
    CHECK(nd::rotation_matrix(n, zero).data() == nd::Matrix::identity(n).data());
    CHECK(nd::rotation_matrix_by_rows(n, zero).data() == nd::Matrix::identity(n).data());
    CHECK(nd::model_matrix(nd::Transform::identity(n)).data() ==
          nd::Matrix::identity(n + 1).data());
}

TEST_CASE("a quarter turn in plane (a, b) sends e_a to e_b and e_b to -e_a", "[ndim]") {
    const int n = 5;
    for (int p = 0; p < nd::plane_count(n); ++p) {
        const auto [a, b] = nd::plane_axes(n, p);
        nd::Transform t = nd::Transform::identity(n);
        t.angles[size_t(p)] = pi / 2;
        std::vector<float> ea(n, 0.0f), eb(n, 0.0f), out(n);
        ea[size_t(a)] = 1.0f;
        eb[size_t(b)] = 1.0f;
        nd::transform_point(t, ea, out);
        for (int k = 0; k < n; ++k) CHECK(out[size_t(k)] == Approx(eb[size_t(k)]).margin(1e-6));
        nd::transform_point(t, eb, out);
        for (int k = 0; k < n; ++k) CHECK(out[size_t(k)] == Approx(-ea[size_t(k)]).margin(1e-6));
        // The matrix says the same: column a of R is e_b.
        const nd::Matrix r = nd::rotation_matrix(n, t.angles);
        for (int k = 0; k < n; ++k) CHECK(r(k, a) == Approx(eb[size_t(k)]).margin(1e-6));
    }
}

TEST_CASE("the plane order: (0,1) acts first, then (0,2)", "[ndim]") {
    // Quarter turns in (0,1) then (0,2): e_0 -> e_1 (the (0,2) turn leaves e_1
    // alone). The other order would give e_0 -> e_2 -> e_2 (then (0,1) leaves
    // e_2 alone); so this pins the order down.
    nd::Transform t = nd::Transform::identity(3);
    t.angles = {pi / 2, pi / 2, 0.0f};
    const std::vector<float> e0 = {1, 0, 0};
    std::vector<float> out(3);
    nd::transform_point(t, e0, out);
    CHECK(out[0] == Approx(0.0f).margin(1e-6));
    CHECK(out[1] == Approx(1.0f));
    CHECK(out[2] == Approx(0.0f).margin(1e-6));
    // And e_1 -> -e_0 -> -e_2.
    const std::vector<float> e1 = {0, 1, 0};
    nd::transform_point(t, e1, out);
    CHECK(out[2] == Approx(-1.0f));
}

TEST_CASE("the matrix path and the per-plane path agree", "[ndim]") {
    const int n = GENERATE(3, 4, 6, 12);
    const nd::Transform t = random_transform(n, uint32_t(7 * n));
    const nd::Matrix naive = nd::model_matrix(t);
    const nd::Matrix by_rows = nd::model_matrix_by_rows(t);
    REQUIRE(naive.size() == n + 1);
    for (size_t k = 0; k < naive.data().size(); ++k)
        CHECK(naive.data()[k] == Approx(by_rows.data()[k]).margin(1e-5));
    // The bottom row is (0, ..., 0, 1).
    for (int col = 0; col < n; ++col) CHECK(naive(n, col) == 0.0f);
    CHECK(naive(n, n) == 1.0f);
    // The rotation alone, both ways.
    const nd::Matrix r1 = nd::rotation_matrix(n, t.angles),
                     r2 = nd::rotation_matrix_by_rows(n, t.angles);
    for (size_t k = 0; k < r1.data().size(); ++k)
        CHECK(r1.data()[k] == Approx(r2.data()[k]).margin(1e-5));
    // Every vertex of the n-cube, through the matrix and plane by plane.
    const nd::Mesh cube = nd::make_cube(n, 1.0f);
    std::vector<float> a(static_cast<size_t>(n)), b(static_cast<size_t>(n));
    float worst = 0.0f;
    for (size_t i = 0; i < cube.vertex_count(); ++i) {
        nd::transform_point(naive, cube.vertex(i), a);
        nd::transform_point(t, cube.vertex(i), b);
        worst = std::max(worst, distance(a, b));
    }
    CHECK(worst < 1e-4f);
}

TEST_CASE("scale, then rotate, then translate", "[ndim]") {
    // Scale (2, 1, 1), quarter turn in (0,1), move by (10, 20, 30):
    // e_0 -> (2, 0, 0) -> (0, 2, 0) -> (10, 22, 30). Rotating first would give
    // (0, 1, 0) -> (0, 1, 0) -> (10, 21, 30).
    nd::Transform t = nd::Transform::identity(3);
    t.scale = {2, 1, 1};
    t.angles = {pi / 2, 0, 0};
    t.position = {10, 20, 30};
    const std::vector<float> e0 = {1, 0, 0};
    std::vector<float> a(3), b(3);
    nd::transform_point(t, e0, a);
    nd::transform_point(nd::model_matrix(t), e0, b);
    for (const auto& out : {a, b}) {
        CHECK(out[0] == Approx(10.0f));
        CHECK(out[1] == Approx(22.0f));
        CHECK(out[2] == Approx(30.0f));
    }
    CHECK(t.packed() == std::vector<float>{10, 20, 30, 2, 1, 1, pi / 2, 0, 0});
    CHECK(t.packed().size() == size_t(3 * (3 + 3) / 2));
}

TEST_CASE("projection to 2D, one dimension at a time, worked by hand", "[ndim]") {
    float out[2];
    // d = 4: (1,1,1,1) -> x 4/3 -> (4/3, 4/3, 4/3) -> x 4/(4 - 4/3) = 3/2 -> (2, 2).
    const std::vector<float> p = {1, 1, 1, 1};
    REQUIRE(nd::project_to_2d(p, nd::Projection::perspective, 4.0f, out));
    CHECK(out[0] == Approx(2.0f));
    CHECK(out[1] == Approx(2.0f));
    // (0.5,...) -> x 8/7 -> (4/7, 4/7, 4/7) -> x 4/(4 - 4/7) = 7/6 -> (2/3, 2/3).
    const std::vector<float> q = {0.5f, 0.5f, 0.5f, 0.5f};
    REQUIRE(nd::project_to_2d(q, nd::Projection::perspective, 4.0f, out));
    CHECK(out[0] == Approx(2.0f / 3.0f));
    CHECK(out[1] == Approx(2.0f / 3.0f));
    // 3D, d = 2: (1, -1, 1) is halfway to the eye: factor 2.
    const std::vector<float> r = {1, -1, 1};
    REQUIRE(nd::project_to_2d(r, nd::Projection::perspective, 2.0f, out));
    CHECK(out[0] == Approx(2.0f));
    CHECK(out[1] == Approx(-2.0f));
    // A point behind the axis' origin shrinks: (3, 3, -2) with d = 2 -> x 1/2.
    const std::vector<float> behind_origin = {3, 3, -2};
    REQUIRE(nd::project_to_2d(behind_origin, nd::Projection::perspective, 2.0f, out));
    CHECK(out[0] == Approx(1.5f));
    // 2D stays as it is.
    const std::vector<float> flat = {0.25f, -7};
    REQUIRE(nd::project_to_2d(flat, nd::Projection::perspective, 4.0f, out));
    CHECK(out[0] == 0.25f);
    CHECK(out[1] == -7.0f);
}

TEST_CASE("orthographic projection drops coordinates", "[ndim]") {
    float out[2];
    const std::vector<float> p = {1, 2, 3, 100, -100};
    REQUIRE(nd::project_to_2d(p, nd::Projection::orthographic, 4.0f, out));
    CHECK(out[0] == 1.0f);
    CHECK(out[1] == 2.0f);
    // The limit d -> infinity of perspective is orthographic.
    REQUIRE(nd::project_to_2d(p, nd::Projection::perspective, 1e7f, out));
    CHECK(out[0] == Approx(1.0f).epsilon(1e-4));
    CHECK(out[1] == Approx(2.0f).epsilon(1e-4));
}

TEST_CASE("points at or behind the eye are clipped, never divided by zero", "[ndim]") {
    float out[2] = {42.0f, 42.0f};
    // On the eye (x_3 = d).
    const std::vector<float> at_eye = {1, 1, 0, 4};
    CHECK_FALSE(nd::project_to_2d(at_eye, nd::Projection::perspective, 4.0f, out));
    // Behind it.
    const std::vector<float> behind = {1, 1, 0, 5};
    CHECK_FALSE(nd::project_to_2d(behind, nd::Projection::perspective, 4.0f, out));
    // In front of the first eye, but pushed onto the second by the first
    // step: (0, 0, 2, 2), d = 4: x 2 -> (0, 0, 4): on the eye of step two.
    const std::vector<float> later = {0, 0, 2, 2};
    CHECK_FALSE(nd::project_to_2d(later, nd::Projection::perspective, 4.0f, out));
    CHECK(out[0] == 42.0f);  // untouched
    CHECK(std::isfinite(out[1]));
}

TEST_CASE("no point within radius r is clipped when d > r sqrt(n - 2)", "[ndim]") {
    const int n = GENERATE(3, 4, 8, 12);
    const float r = 1.0f;
    const float d = 1.01f * nd::safe_eye_distance(n, r);
    std::mt19937 rng{static_cast<uint32_t>(n)};
    std::normal_distribution<float> normal;
    std::vector<float> x(static_cast<size_t>(n));
    int clipped = 0;
    for (int i = 0; i < 20000; ++i) {
        for (float& c : x) c = normal(rng);
        x[0] = x[1] = 0.0f;  // only coordinates 2..n-1 matter
        const float scale = r / length(x);
        for (float& c : x) c *= scale;
        float out[2];
        clipped += nd::project_to_2d(x, nd::Projection::perspective, d, out) ? 0 : 1;
    }
    CHECK(clipped == 0);
    // And the worst case is real: at n = 4, the point (0, 0, t, u) with u =
    // r^2/d and t = sqrt(r^2 - u^2) lands exactly on the second eye when
    // d = r sqrt(2).
    const float d4 = nd::safe_eye_distance(4, r);
    CHECK(d4 == Approx(std::sqrt(2.0f)));
    const float u = r * r / d4;
    const std::vector<float> worst = {0, 0, std::sqrt(r * r - u * u), u};
    // After step one: x_2 = t d / (d - u) = 1 / sqrt(0.5) * ... = d exactly.
    const float x2 = worst[2] * d4 / (d4 - u);
    CHECK(x2 == Approx(d4));
}

TEST_CASE("make_cube refuses impossible dimensions", "[ndim]") {
    CHECK_THROWS_AS(nd::make_cube(0, 1.0f), std::invalid_argument);
    CHECK_THROWS_AS(nd::make_cube(21, 1.0f), std::invalid_argument);
}

TEST_CASE("the scenes of chapters 18-20", "[ndim]") {
    const nd::Scene pair = nd::make_scene("default", 4, false);
    CHECK(pair.objects.size() == 2);
    CHECK(pair.line_count() == 32 + 96);
    const nd::Scene one = nd::make_scene("cube", 12, false);
    CHECK(one.objects.size() == 1);
    CHECK(one.line_count() == 24576);
    const nd::Scene many = nd::make_scene("many", 8, false);
    CHECK(many.objects.size() == 250);
    CHECK(many.line_count() == 250u * 1024u);
    // The same seed, the same scene: every number equal.
    const nd::Scene again = nd::make_scene("many", 8, false);
    bool same = true;
    for (size_t i = 0; i < many.objects.size(); ++i)
        same = same && many.objects[i].start.packed() == again.objects[i].start.packed() &&
               many.objects[i].spin == again.objects[i].spin;
    CHECK(same);
    // Still: every angle and spin 0.
    const nd::Scene still = nd::make_scene("cube", 3, true);
    CHECK(still.objects[0].start.packed() == std::vector<float>{0, 0, 0, 1, 1, 1, 0, 0, 0});
    CHECK(still.objects[0].spin == std::vector<float>{0, 0, 0});
    // at(): start + spin * time.
    const nd::SceneObject& o = pair.objects[0];
    const nd::Transform t = o.at(2.0f);
    for (size_t p = 0; p < t.angles.size(); ++p)
        CHECK(t.angles[p] == Approx(o.start.angles[p] + 2.0f * o.spin[p]));
    CHECK_THROWS_AS(nd::make_scene("default", 5, false), std::invalid_argument);
    CHECK_THROWS_AS(nd::make_scene("hypersphere", 4, false), std::invalid_argument);
}

TEST_CASE("no vertex of any scene is ever clipped", "[ndim]") {
    for (const auto& [name, n] : std::vector<std::pair<const char*, int>>{
             {"default", 4}, {"cube", 3}, {"cube", 12}, {"many", 4}, {"many", 12}}) {
        const nd::Scene scene = nd::make_scene(name, n, false);
        int clipped = 0;
        std::vector<float> world(static_cast<size_t>(n));
        for (float time : {0.0f, 1.7f, 25.0f, 400.0f})
            for (size_t i = 0; i < scene.objects.size();
                 i += name == std::string("many") ? 25 : 1) {
                const nd::SceneObject& object = scene.objects[i];
                const nd::Mesh& mesh = scene.meshes[size_t(object.mesh)];
                const nd::Matrix model = nd::model_matrix_by_rows(object.at(time));
                for (size_t v = 0; v < mesh.vertex_count(); ++v) {
                    nd::transform_point(model, mesh.vertex(v), world);
                    float xy[2];
                    clipped += nd::project_to_2d(world, nd::Projection::perspective, scene.eye, xy)
                                   ? 0
                                   : 1;
                }
            }
        INFO(name << " n = " << n);
        CHECK(clipped == 0);
    }
}
