// The plain C interface between sfrender (image_file.cpp) and its
// OpenImageIO module (oiio_module.cpp), which image_file.cpp loads with
// dlopen: nothing of OpenImageIO crosses it. Both sides include this file,
// and the two are built together, so that they cannot disagree.
#pragma once

#include <cstddef>

extern "C" {

// How the file stores a channel.
enum SfrenderPixelType {
  kSfrenderUint8 = 0,   // `pixels` holds bytes, the levels to store
  kSfrenderUint16 = 1,  // `pixels` holds uint16_t levels
  kSfrenderHalf = 2,    // `pixels` holds floats, stored as half (within its range)
  kSfrenderFloat = 3,   // `pixels` holds floats
};

// An image to write, row by row from the top.
struct SfrenderImageData {
  int width;
  int height;
  int channels;   // 3 (RGB) or 4 (RGBA)
  int pixelType;  // SfrenderPixelType
  const void* pixels;
  int linear;         // 1: linear values, Rec. 709 primaries and D65 white; 0: sRGB display values
  int straightAlpha;  // 1: the colour of a pixel is not multiplied by its alpha; 0: it is
  // Where the image lies in the full image it is a region of (EXR's data
  // window within its display window; a TIFF's position), and the full
  // image's size: 0, 0, width, height for a whole image.
  int x;
  int y;
  int fullWidth;
  int fullHeight;
};

// A region of an image read back (sfrender --merge): its data window, the
// display window it lies in, its channels and how it stores them.
struct SfrenderImageRegion {
  int x, y, width, height;                  // the data window: the pixels stored
  int fullX, fullY, fullWidth, fullHeight;  // the display window
  int channels;
  int bits;      // bits a channel of the file: 8, 16, 32
  int floating;  // 1: floating-point channels (EXR's half or float), 0: integers
};

// The formats sfrender can write through OpenImageIO, one a line: the
// format's name in OpenImageIO, 1 or 0 for whether its writer stores alpha,
// and the extensions its writer is found by, without their dot
// ("openexr 1 exr sxr mxr\n"). Writes at most `size` bytes, the last a
// '\0', and returns the length of the whole list, as snprintf does.
typedef std::size_t (*SfrenderOiioFormats)(char* list, std::size_t size);

// Writes the image, in the format of `name`'s extension, into the empty file
// open as `fd`, a file in memory (memory_file.h) that sfrender then writes
// to the target by checked writes: OpenImageIO's writers do not all report
// a short write (BMP, Targa, SGI, FITS, JPEG 2000, WebP write through stdio
// and go on; libjpeg ends the process). Returns 1 on success, or 0 with a
// message in `error`.
typedef int (*SfrenderOiioWrite)(const char* name, const SfrenderImageData* image, int fd,
                                 char* error, std::size_t errorSize);

// Reads the OpenEXR file at `path` (--merge's tiles are EXR, and no other
// of OpenImageIO's readers is tried, so that a stranger's bytes meet one
// parser, not every one OpenImageIO has): with `pixels` null, only its
// region (`region`); otherwise also its first three channels as floats,
// row by row from the top of the data window, into `pixels`, which holds
// `capacity` floats. Returns 1; -1 when the file is not OpenEXR; or 0 with
// a message in `error`.
typedef int (*SfrenderOiioRead)(const char* path, SfrenderImageRegion* region, float* pixels,
                                std::size_t capacity, char* error, std::size_t errorSize);

// Their names in the module.
#define SFRENDER_OIIO_FORMATS "sfrender_oiio_formats"
#define SFRENDER_OIIO_WRITE "sfrender_oiio_write"
#define SFRENDER_OIIO_READ "sfrender_oiio_read"

}  // extern "C"
