// The one translation unit that holds stb_image_write (public domain, Sean Barrett).
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image_write.h>
