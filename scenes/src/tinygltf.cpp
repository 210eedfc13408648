// tinygltf's implementation, compiled once (with the macros of tinygltf.hpp).
#define TINYGLTF_IMPLEMENTATION
#include "tinygltf.hpp"
