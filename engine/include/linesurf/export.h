#pragma once
/* @file export.h
 * @brief LINESURF_API marks the symbols the linesurf shared library exports; everything else is
 * built with hidden visibility (C and C++). */

#if defined(LINESURF_STATIC_DEFINE)
#define LINESURF_API
#elif defined(_WIN32)
#if defined(LINESURF_BUILDING_LIBRARY)
#define LINESURF_API __declspec(dllexport)
#else
#define LINESURF_API __declspec(dllimport)
#endif
#else
#define LINESURF_API __attribute__((visibility("default")))
#endif
