// A fixture for the book tests (book/CMakeLists.txt): two constants a page quotes.
const uint TILE_SIZE = 16;          // a tile is 16 x 16 pixels
const uint MAX_TILE_LIGHTS = 2048;  // the longest list a tile stores
