// Numbers in a COLLADA document that Assimp's importer uses without checking: an array's count
// (count="-1" made it reserve 2^32 values and crash), an accessor's stride and offset (a stride
// of 10^9 read past the array: SIGSEGV), the words of a float array ("1,5" was read as 1.5),
// the unit (meter="-1" mirrored the model through the origin) and the up axis (an unknown one
// was ignored). A light scan of the XML refuses them, naming the element, before Assimp reads
// the file.
#pragma once
#include <string>
#include <string_view>

namespace zraster::io {

// Throws InputError(file, "malformed COLLADA file: ...") for
//   <float_array>, <int_array>  a count that is not a whole number, fewer words than the count,
//                               or a word that is not a number of the array's type (xs:float:
//                               decimal with optional exponent, INF, -INF, NaN);
//   <accessor>                  a count, offset or stride that is not a whole number, a stride of
//                               0 or less than its <param>s, or elements past the end of the
//                               array it names (when that array is in the file);
//   <unit meter>                not a positive finite number;
//   <up_axis>                   other than X_UP, Y_UP, Z_UP.
void check_collada_values(std::string_view document, const std::string& file);

}  // namespace zraster::io
