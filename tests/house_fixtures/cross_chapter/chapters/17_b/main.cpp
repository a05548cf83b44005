#include "../16_a/scene.hpp"
int main() {}
