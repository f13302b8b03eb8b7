// The one translation unit that compiles stb's image reader and writer.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#pragma GCC diagnostic ignored "-Wconversion"
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#define STBI_ONLY_HDR
// The largest image (image.hpp); the readers check it, and the file size, first.
#define STBI_MAX_DIMENSIONS (1 << 15)
#include <stb_image.h>
#include <stb_image_write.h>
#pragma GCC diagnostic pop
