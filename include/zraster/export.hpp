// ZRASTER_API marks the public API: what a shared zraster library exports. Everything else in the
// libraries is hidden (-fvisibility=hidden), so a shared build's symbol table is the API.
// Static builds (the default) need nothing: the macro is then empty.
#pragma once

#if defined(ZRASTER_SHARED)
#if defined(_WIN32)
#if defined(ZRASTER_BUILDING)
#define ZRASTER_API __declspec(dllexport)
#else
#define ZRASTER_API __declspec(dllimport)
#endif
#elif defined(__GNUC__) || defined(__clang__)
#define ZRASTER_API __attribute__((visibility("default")))
#else
#define ZRASTER_API
#endif
#else
#define ZRASTER_API
#endif
