// One marker for every physical law: the same inline function is compiled for the CPU backend
// by the host compiler and for the CUDA kernels by nvcc (as HOOMD-blue's evaluators and Box2D's
// B2_INLINE do). Nothing in physics/ may include ROS, CUDA runtime or STL container headers.
#pragma once

#if defined(__CUDACC__)
#define TIS_HD __host__ __device__ __forceinline__
#else
#define TIS_HD inline
#endif
