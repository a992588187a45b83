// tinygltf's implementation, compiled here (Debian's README.Debian, second route) rather than
// linked from libtinygltf.so, so that sanitizer builds instrument the parser that reads
// hostile files too. Images are not decoded by tinygltf (no stb): the loader keeps the
// encoded bytes and decodes the one PNG it needs with libpng
// (TINYGLTF_NO_STB_IMAGE and TINYGLTF_NO_STB_IMAGE_WRITE: samples/CMakeLists.txt).
#define TINYGLTF_IMPLEMENTATION
#include <tiny_gltf.h>
