// n-dimensional meshes, transforms and projection (vkt/domains/ndim.hpp, chapter 18).
#include "vkt/domains/ndim.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace vkt::ndim {

float Mesh::radius() const {
    float r2 = 0.0f;
    for (size_t i = 0; i < vertex_count(); ++i) {
        float sum = 0.0f;
        for (float c : vertex(i)) sum += c * c;
        r2 = std::max(r2, sum);
    }
    return std::sqrt(r2);
}

Mesh make_cube(int n, float s) {
    if (n < 1 || n > 20)
        throw std::invalid_argument("make_cube: n must be from 1 to 20, not " + std::to_string(n));
    Mesh mesh;
    mesh.dim = n;
    const uint32_t count = 1u << n;
    mesh.coords.resize(size_t(count) * size_t(n));
    for (uint32_t i = 0; i < count; ++i)
        for (int j = 0; j < n; ++j)
            mesh.coords[size_t(i) * size_t(n) + size_t(j)] = (i >> j) & 1u ? s : -s;
    // Axis by axis: every vertex with bit k clear and its neighbour across k.
    mesh.edges.reserve(size_t(n) * (count / 2));
    for (int k = 0; k < n; ++k)
        for (uint32_t i = 0; i < count; ++i)
            if (!((i >> k) & 1u)) mesh.edges.push_back({i, i | (1u << k)});
    return mesh;
}

Mesh make_24_cell(float s) {
    Mesh mesh;
    mesh.dim = 4;
    for (int axis = 0; axis < 4; ++axis)
        for (float sign : {1.0f, -1.0f}) {
            float v[4] = {0, 0, 0, 0};
            v[axis] = sign * s;
            mesh.coords.insert(mesh.coords.end(), v, v + 4);
        }
    for (uint32_t bits = 0; bits < 16; ++bits)
        for (int j = 0; j < 4; ++j) mesh.coords.push_back((bits >> j) & 1u ? -0.5f * s : 0.5f * s);
    // The edges are the nearest pairs, at distance s; the next nearest are at
    // s * sqrt(2), so a tolerance of a tenth of s^2 cannot mistake them.
    const size_t count = mesh.vertex_count();
    for (size_t a = 0; a < count; ++a)
        for (size_t b = a + 1; b < count; ++b) {
            float d2 = 0.0f;
            for (int j = 0; j < 4; ++j) {
                const float d = mesh.vertex(a)[size_t(j)] - mesh.vertex(b)[size_t(j)];
                d2 += d * d;
            }
            if (std::abs(d2 - s * s) < 0.1f * s * s)
                mesh.edges.push_back({uint32_t(a), uint32_t(b)});
        }
    return mesh;
}

std::pair<int, int> plane_axes(int n, int p) {
    if (p < 0 || p >= plane_count(n)) throw std::out_of_range("plane_axes: no such plane");
    for (int i = 0; i < n - 1; ++i) {
        const int in_row = n - 1 - i;  // planes (i, i+1) .. (i, n-1)
        if (p < in_row) return {i, i + 1 + p};
        p -= in_row;
    }
    return {-1, -1};  // unreachable
}

int plane_index(int n, int i, int j) {
    if (i < 0 || j <= i || j >= n) throw std::out_of_range("plane_index: need 0 <= i < j < n");
    // The rows before i hold (n-1) + (n-2) + ... + (n-i) planes.
    return i * (2 * n - i - 1) / 2 + (j - i - 1);
}

Transform Transform::identity(int n) {
    return {std::vector<float>(size_t(n), 0.0f), std::vector<float>(size_t(n), 1.0f),
            std::vector<float>(size_t(plane_count(n)), 0.0f)};
}

std::vector<float> Transform::packed() const {
    std::vector<float> out(position);
    out.insert(out.end(), scale.begin(), scale.end());
    out.insert(out.end(), angles.begin(), angles.end());
    return out;
}

// [per-plane]
void transform_point(const Transform& t, std::span<const float> x, std::span<float> out) {
    const int n = t.dim();
    for (int k = 0; k < n; ++k) out[size_t(k)] = x[size_t(k)] * t.scale[size_t(k)];
    int p = 0;
    for (int i = 0; i < n; ++i)
        for (int j = i + 1; j < n; ++j, ++p) {
            const float c = std::cos(t.angles[size_t(p)]), s = std::sin(t.angles[size_t(p)]);
            const float xi = out[size_t(i)], xj = out[size_t(j)];
            out[size_t(i)] = c * xi - s * xj;
            out[size_t(j)] = s * xi + c * xj;
        }
    for (int k = 0; k < n; ++k) out[size_t(k)] += t.position[size_t(k)];
}
// [/per-plane]

Matrix Matrix::identity(int n) {
    Matrix m(n);
    for (int i = 0; i < n; ++i) m(i, i) = 1.0f;
    return m;
}

Matrix operator*(const Matrix& a, const Matrix& b) {
    const int n = a.size();
    Matrix c(n);
    for (int i = 0; i < n; ++i)
        for (int k = 0; k < n; ++k) {
            const float aik = a(i, k);
            for (int j = 0; j < n; ++j) c(i, j) += aik * b(k, j);
        }
    return c;
}

Matrix plane_rotation(int n, int i, int j, float angle) {
    Matrix r = Matrix::identity(n);
    const float c = std::cos(angle), s = std::sin(angle);
    r(i, i) = c;
    r(j, j) = c;
    r(i, j) = -s;
    r(j, i) = s;
    return r;
}

Matrix rotation_matrix(int n, std::span<const float> angles) {
    Matrix r = Matrix::identity(n);
    int p = 0;
    for (int i = 0; i < n; ++i)
        for (int j = i + 1; j < n; ++j, ++p) r = plane_rotation(n, i, j, angles[size_t(p)]) * r;
    return r;
}

// [rotate-rows]
// R_ij * M: row i becomes c*row_i - s*row_j, row j becomes s*row_i + c*row_j;
// every other row stays.
static void rotate_rows(Matrix& m, int i, int j, float angle) {
    const float c = std::cos(angle), s = std::sin(angle);
    for (int col = 0; col < m.size(); ++col) {
        const float a = m(i, col), b = m(j, col);
        m(i, col) = c * a - s * b;
        m(j, col) = s * a + c * b;
    }
}
// [/rotate-rows]

Matrix rotation_matrix_by_rows(int n, std::span<const float> angles) {
    Matrix r = Matrix::identity(n);
    int p = 0;
    for (int i = 0; i < n; ++i)
        for (int j = i + 1; j < n; ++j, ++p) rotate_rows(r, i, j, angles[size_t(p)]);
    return r;
}

// [model-naive]
Matrix model_matrix(const Transform& t) {
    const int n = t.dim();
    Matrix scale = Matrix::identity(n + 1);
    Matrix translate = Matrix::identity(n + 1);
    for (int k = 0; k < n; ++k) {
        scale(k, k) = t.scale[size_t(k)];
        translate(k, n) = t.position[size_t(k)];
    }
    // Scale first, then every plane in order, then translate: each a full
    // (n+1)x(n+1) product, the way one would write it down.
    Matrix m = scale;
    int p = 0;
    for (int i = 0; i < n; ++i)
        for (int j = i + 1; j < n; ++j, ++p)
            m = plane_rotation(n + 1, i, j, t.angles[size_t(p)]) * m;
    return translate * m;
}
// [/model-naive]

Matrix model_matrix_by_rows(const Transform& t) {
    const int n = t.dim();
    Matrix m = Matrix::identity(n + 1);
    for (int k = 0; k < n; ++k) m(k, k) = t.scale[size_t(k)];
    int p = 0;
    for (int i = 0; i < n; ++i)
        for (int j = i + 1; j < n; ++j, ++p) rotate_rows(m, i, j, t.angles[size_t(p)]);
    // The rotation leaves the last column (0, ..., 0, 1) alone; T only sets it.
    for (int k = 0; k < n; ++k) m(k, n) = t.position[size_t(k)];
    return m;
}

void transform_point(const Matrix& model, std::span<const float> x, std::span<float> out) {
    const int n = model.size() - 1;
    for (int row = 0; row < n; ++row) {
        float sum = model(row, n);  // times the homogeneous 1
        for (int col = 0; col < n; ++col) sum += model(row, col) * x[size_t(col)];
        out[size_t(row)] = sum;
    }
}

double determinant(const Matrix& m) {
    const int n = m.size();
    std::vector<double> a(m.data().begin(), m.data().end());
    double det = 1.0;
    // Row r, column c of the n x n matrix, indexed in size_t from the start.
    const auto at = [&a, n](int r, int c) -> double& {
        return a[size_t(r) * size_t(n) + size_t(c)];
    };
    for (int col = 0; col < n; ++col) {
        int pivot = col;
        for (int row = col + 1; row < n; ++row)
            if (std::abs(at(row, col)) > std::abs(at(pivot, col))) pivot = row;
        if (at(pivot, col) == 0.0) return 0.0;
        if (pivot != col) {
            for (int k = 0; k < n; ++k) std::swap(at(pivot, k), at(col, k));
            det = -det;
        }
        const double diagonal = at(col, col);
        det *= diagonal;
        for (int row = col + 1; row < n; ++row) {
            const double f = at(row, col) / diagonal;
            for (int k = col; k < n; ++k) at(row, k) -= f * at(col, k);
        }
    }
    return det;
}

// [project]
bool project_to_2d(std::span<const float> x, Projection kind, float d, float out[2]) {
    const size_t n = x.size();
    if (n < 2) throw std::invalid_argument("project_to_2d: a point needs at least 2 coordinates");
    // Every step multiplies all the remaining coordinates by the same factor,
    // so one running factor f carries them all: after the steps so far,
    // coordinate k is f * x[k].
    float f = 1.0f;
    if (kind == Projection::perspective)
        for (size_t k = n - 1; k >= 2; --k) {
            const float distance = d - f * x[k];   // from the eye, along axis k
            if (!(distance > 0.0f)) return false;  // at or behind the eye (or NaN)
            f *= d / distance;
        }
    out[0] = f * x[0];
    out[1] = f * x[1];
    return true;
}
// [/project]

float safe_eye_distance(int n, float r) {
    return r * std::sqrt(float(std::max(n - 2, 0)));
}

Transform SceneObject::at(float time) const {
    Transform t = start;
    for (size_t p = 0; p < t.angles.size(); ++p) t.angles[p] += spin[p] * time;
    return t;
}

size_t Scene::line_count() const {
    size_t lines = 0;
    for (const SceneObject& object : objects) lines += meshes[size_t(object.mesh)].edges.size();
    return lines;
}

namespace {

// A reproducible generator, the same on every machine (the standard
// distributions are not): 24 random bits of a 32-bit xorshift as a float.
struct Random {
    uint32_t state;
    float uniform(float lo, float hi) {
        state ^= state << 13;
        state ^= state >> 17;
        state ^= state << 5;
        return lo + (hi - lo) * float(state >> 8) * (1.0f / 16777216.0f);
    }
};

}  // namespace

// [scenes]
// Object radii r and the eye distance: with d > r sqrt(n - 2) no vertex can
// reach the eye (the appendix derives it); twice that keeps a clear
// perspective without clipping. Objects sit side by side along axes 0 and 1,
// the two that reach the screen.
Scene make_scene(std::string_view name, int n, bool still) {
    if (n < 2 || n > 20)
        throw std::invalid_argument("make_scene: n must be from 2 to 20, not " + std::to_string(n));
    if (name == "default" && n != 4)
        throw std::invalid_argument("make_scene: the default scene is 4-dimensional");
    Scene scene;
    scene.dim = n;
    Random random{18u};
    const int planes = plane_count(n);
    auto object_at = [&](int mesh, float x, float y) {
        SceneObject object{mesh, Transform::identity(n), std::vector<float>(size_t(planes))};
        object.start.position[0] = x;
        object.start.position[1] = y;
        for (int p = 0; p < planes; ++p) {
            object.start.angles[size_t(p)] = still ? 0.0f : random.uniform(-0.6f, 0.6f);
            object.spin[size_t(p)] = still ? 0.0f : random.uniform(-0.5f, 0.5f);
        }
        return object;
    };
    if (name == "default") {
        scene.meshes = {make_cube(4, 1.0f), make_24_cell(2.0f)};  // both of radius 2
        scene.objects = {object_at(0, -3.0f, 0.0f), object_at(1, 3.0f, 0.0f)};
        scene.eye = 2.0f * safe_eye_distance(4, 2.0f);
        scene.view_half_height = 4.3f;
    } else if (name == "cube") {
        scene.meshes = {make_cube(n, 1.0f)};
        scene.objects = {object_at(0, 0.0f, 0.0f)};
        const float r = std::sqrt(float(n));
        scene.eye = 2.0f * safe_eye_distance(n, r);
        scene.view_half_height = 1.5f * r;
    } else if (name == "many") {  // 250 n-cubes scattered over a 4:3 field
        scene.meshes = {make_cube(n, 1.0f)};
        const float r = std::sqrt(float(n)), field = 9.0f * r;
        for (int i = 0; i < 250; ++i) {
            const float x = random.uniform(-field * 4.0f / 3.0f, field * 4.0f / 3.0f);
            const float y = random.uniform(-field, field);
            scene.objects.push_back(object_at(0, x, y));
        }
        // A cube far off the axis is stretched by about its offset times its
        // depth over d, as in a wide-angle lens: the eye stands further back.
        scene.eye = std::max(2.0f * safe_eye_distance(n, r), 3.0f * field);
        scene.view_half_height = field + 1.5f * r;
    } else {
        throw std::invalid_argument("make_scene: no scene called '" + std::string(name) + "'");
    }
    return scene;
}
// [/scenes]

}  // namespace vkt::ndim
