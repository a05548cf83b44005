#pragma once
// Objects of n dimensions, the mathematics of chapters 18-20 (taught in
// chapter 18; derived in the book's appendix "The mathematics of n
// dimensions"): wire-frame meshes (the n-cube, the 24-cell), transforms made
// of a position, a scale and one angle per rotation plane, their
// (n+1)x(n+1) homogeneous matrices, and projection from n dimensions down to 2
// one dimension at a time. Plain C++ with a run-time n: glm stops at 4.
//
// Conventions, used everywhere in chapters 18-20:
// - A point is n floats; vertex i of a mesh is coords[i*n .. i*n + n).
// - Rotation planes are the axis pairs (i, j), i < j, in lexicographic order:
//   (0,1), (0,2), ..., (0,n-1), (1,2), ..., (n-2,n-1); plane p has angle p.
// - R_ij(a) is the identity except R[i][i] = R[j][j] = cos a,
//   R[i][j] = -sin a, R[j][i] = sin a: it turns e_i towards e_j.
// - The rotation is R = R_last * ... * R_(0,2) * R_(0,1): applied to a point,
//   plane (0,1) acts FIRST, then (0,2), and so on in lexicographic order.
// - A transform scales, then rotates, then translates: x' = p + R (s * x).
// - Matrices are row-major and act on column vectors: x' = M x.

#include <cstdint>
#include <span>
#include <string_view>
#include <utility>
#include <vector>

namespace vkt::ndim {

// ---- Meshes ------------------------------------------------------------------

struct Edge {
    uint32_t a, b;  // vertex indices
};

// A wire frame in R^dim: vertices and the edges between them.
struct Mesh {
    int dim = 0;
    std::vector<float> coords;  // vertex_count() * dim floats
    std::vector<Edge> edges;

    size_t vertex_count() const { return dim > 0 ? coords.size() / size_t(dim) : 0; }
    std::span<const float> vertex(size_t i) const {
        return {coords.data() + i * size_t(dim), size_t(dim)};
    }
    // The largest distance of a vertex from the origin.
    float radius() const;
};

// The n-cube of half side s: 2^n vertices, coordinate j of vertex i is -s or
// +s by bit j of i; n * 2^(n-1) edges joining the vertices one bit apart,
// grouped by axis: edges [k * 2^(n-1), (k+1) * 2^(n-1)) run along axis k, each
// from the vertex with bit k clear to the one with it set. 1 <= n <= 20.
Mesh make_cube(int n, float s);

// Which axis edge e of make_cube(n, ...) runs along.
inline int cube_edge_axis(int n, size_t e) {
    return int(e >> (n - 1));
}

// The 24-cell of radius s (4D): the 8 points +-s e_k and the 16 points
// (+-s/2, +-s/2, +-s/2, +-s/2); its 96 edges join the pairs at distance s.
Mesh make_24_cell(float s);

// ---- Rotation planes and transforms ------------------------------------------

inline int plane_count(int n) {
    return n * (n - 1) / 2;
}
// The axes (i, j), i < j, of plane p (lexicographic order), and back.
std::pair<int, int> plane_axes(int n, int p);
int plane_index(int n, int i, int j);

// n(n+3)/2 numbers: where, how large along each axis, how turned in each plane.
struct Transform {
    std::vector<float> position;  // n
    std::vector<float> scale;     // n
    std::vector<float> angles;    // plane_count(n), radians

    static Transform identity(int n);  // position 0, scale 1, angles 0
    int dim() const { return int(position.size()); }
    // position, then scale, then angles: the layout chapters 19 and 20 upload.
    std::vector<float> packed() const;
};

// The per-plane path: x' = p + R (s * x), with each plane's rotation applied
// to the point in turn, O(n^2) per point and no matrix at all.
void transform_point(const Transform& t, std::span<const float> x, std::span<float> out);

// ---- Matrices ------------------------------------------------------------------

// A square, row-major matrix of run-time size.
class Matrix {
public:
    Matrix() = default;
    explicit Matrix(int n) : n_(n), a_(size_t(n) * size_t(n), 0.0f) {}
    static Matrix identity(int n);

    int size() const { return n_; }
    float& operator()(int row, int col) { return a_[size_t(row) * size_t(n_) + size_t(col)]; }
    float operator()(int row, int col) const { return a_[size_t(row) * size_t(n_) + size_t(col)]; }
    const std::vector<float>& data() const { return a_; }

private:
    int n_ = 0;
    std::vector<float> a_;
};

// The full product: n^3 multiplications.
Matrix operator*(const Matrix& a, const Matrix& b);

// R_ij(angle) as an n x n matrix.
Matrix plane_rotation(int n, int i, int j, float angle);

// R = R_last * ... * R_(0,1), built naively: one full n x n product per
// plane, so n(n-1)/2 products of n^3 each: O(n^5).
Matrix rotation_matrix(int n, std::span<const float> angles);
// The same R in O(n^3): multiplying by R_ij on the left changes only rows i
// and j, so each plane costs 2n multiply-adds pairs instead of n^3.
Matrix rotation_matrix_by_rows(int n, std::span<const float> angles);

// The (n+1)x(n+1) homogeneous model matrix T * R * S (translate, rotate,
// scale; acting on (x, 1)), built naively from full products: O(n^5).
Matrix model_matrix(const Transform& t);
// The same matrix in O(n^3) (rotation_matrix_by_rows, then scale the columns
// and set the last column).
Matrix model_matrix_by_rows(const Transform& t);

// x' = M (x, 1), dropping the homogeneous 1: (n+1)^2 multiply-adds.
void transform_point(const Matrix& model, std::span<const float> x, std::span<float> out);

// The determinant (Gaussian elimination with partial pivoting, in double).
double determinant(const Matrix& m);

// ---- Projection ---------------------------------------------------------------

enum class Projection {
    perspective,   // the eye on the last axis at distance d
    orthographic,  // drop the last coordinate: the limit d -> infinity
};

// Projects x (n >= 2 coordinates) to 2D one dimension at a time: for
// k = n-1 down to 2, perspective multiplies x_0 .. x_(k-1) by d / (d - x_k)
// and drops x_k; orthographic just drops it. Writes (x_0, x_1) to out and
// returns true, or returns false (out untouched) when the point is at or
// behind the eye at some step (x_k >= d), where the factor would divide by
// zero or flip the point.
bool project_to_2d(std::span<const float> x, Projection kind, float d, float out[2]);

// r * sqrt(n - 2): with an eye distance d greater than this, no point whose
// coordinates 2..n-1 lie within radius r of the origin is ever clipped. The
// appendix derives it: each step can push the remaining coordinates outward,
// and in the worst case 1 / (r/d)^2 drops by exactly 1 per step.
float safe_eye_distance(int n, float r);

// ---- Scenes -------------------------------------------------------------------
// The scenes chapters 18, 19 and 20 all draw, built here so that the three
// draw exactly the same objects and can be compared picture for picture.

struct SceneObject {
    int mesh = 0;             // index into Scene::meshes
    Transform start;          // the pose at time 0
    std::vector<float> spin;  // radians per second, one per plane

    // The pose at `time` seconds: the start angles plus spin * time.
    Transform at(float time) const;
};

struct Scene {
    int dim = 0;
    std::vector<Mesh> meshes;
    std::vector<SceneObject> objects;
    float eye = 0;               // the eye distance d of the projection
    float view_half_height = 0;  // projected units from the centre to the top edge

    size_t line_count() const;  // the edges of every object
};

// "default" (n = 4 only): a tesseract of half side 1 at x = -3 and a 24-cell of
// radius 2 at x = +3. "cube": one n-cube of half side 1 at the origin.
// "many": 250 n-cubes of half side 1 at random places over a 4:3 field. Start
// angles (within +-0.6 rad) and spins (within +-0.5 rad/s) are random too,
// from a fixed seed, unless `still` (all zero). Objects are placed along
// axes 0 and 1 only, and the eye is at least twice safe_eye_distance for their
// radius, so no vertex is ever clipped. Throws std::invalid_argument for an
// unknown name or n outside 2..20 (4 for "default").
Scene make_scene(std::string_view name, int n, bool still);

}  // namespace vkt::ndim
