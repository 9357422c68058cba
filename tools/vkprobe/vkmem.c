// Times host-visible memory on a Vulkan device: allocation, mapping, first touch
// (page faults) and full reads/writes, single-threaded and on N threads.
#include <dlfcn.h>
#include <pthread.h>
#include <stdio.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
typedef int32_t VkResult;
typedef void *VkInstance, *VkPhysicalDevice, *VkDevice;
typedef uint64_t VkDeviceMemory;
typedef void (*PFN)(void);
typedef PFN (*PFN_gipa)(VkInstance, const char *);
typedef struct { int sType; const void *pNext; const char *app; uint32_t appVer; const char *eng; uint32_t engVer; uint32_t api; } AppInfo;
typedef struct { int sType; const void *pNext; uint32_t flags; const AppInfo *app; uint32_t nl; const char *const *l; uint32_t ne; const char *const *e; } InstInfo;
typedef struct { int sType; const void *pNext; uint32_t flags; uint32_t family; uint32_t count; const float *prio; } QueueInfo;
typedef struct { int sType; const void *pNext; uint32_t flags; uint32_t nq; const QueueInfo *q; uint32_t nl; const char *const *l; uint32_t ne; const char *const *e; const void *features; } DevInfo;
typedef struct { uint32_t flags, heap; } MemType;
typedef struct { uint64_t size; uint32_t flags; } MemHeap;
typedef struct { uint32_t ntypes; MemType types[32]; uint32_t nheaps; MemHeap heaps[16]; } MemProps;
typedef struct { int sType; const void *pNext; uint64_t size; uint32_t type; } AllocInfo;
static double now(void) { struct timespec ts; clock_gettime(CLOCK_MONOTONIC, &ts); return ts.tv_sec * 1e3 + ts.tv_nsec / 1e6; }
typedef struct { volatile unsigned char *p; size_t n; int mode; uint64_t sum; } Job;
static void *work(void *a) {
  Job *j = a; uint64_t s = 0;
  if (j->mode == 0) for (size_t i = 0; i < j->n; i += 4096) s += j->p[i];           // touch (read)
  else if (j->mode == 1) { const uint64_t *q = (const uint64_t *)j->p; for (size_t i = 0; i < j->n / 8; i++) s += q[i]; } // read all
  else if (j->mode == 2) memset((void *)j->p, 1, j->n);                             // write all
  j->sum = s; return NULL;
}
static double run(unsigned char *p, size_t n, int mode, int threads) {
  pthread_t t[64]; Job j[64]; double a = now(); size_t part = n / threads;
  for (int i = 0; i < threads; i++) { j[i] = (Job){p + i * part, part, mode, 0}; pthread_create(&t[i], NULL, work, &j[i]); }
  for (int i = 0; i < threads; i++) pthread_join(t[i], NULL);
  return now() - a;
}
int main(int argc, char **argv) {
  int threads = argc > 1 ? atoi(argv[1]) : 16;
  size_t size = 132710400;  // 3840 x 2160 x 16
  void *lib = dlopen("libvulkan.so.1", RTLD_NOW | RTLD_LOCAL);
  PFN_gipa gipa = (PFN_gipa)dlsym(lib, "vkGetInstanceProcAddr");
  VkResult (*createInst)(const InstInfo *, const void *, VkInstance *) = (void *)gipa(NULL, "vkCreateInstance");
  AppInfo app = {0, NULL, "vkmem", 1, "vkmem", 1, (1u << 22) | (3u << 12)};
  InstInfo ii = {1, NULL, 0, &app, 0, NULL, 0, NULL};
  VkInstance inst; if (createInst(&ii, NULL, &inst)) return 1;
  VkResult (*enumPD)(VkInstance, uint32_t *, VkPhysicalDevice *) = (void *)gipa(inst, "vkEnumeratePhysicalDevices");
  void (*memprops)(VkPhysicalDevice, MemProps *) = (void *)gipa(inst, "vkGetPhysicalDeviceMemoryProperties");
  VkResult (*createDev)(VkPhysicalDevice, const DevInfo *, const void *, VkDevice *) = (void *)gipa(inst, "vkCreateDevice");
  PFN_gipa gdpa = (PFN_gipa)gipa(inst, "vkGetDeviceProcAddr");
  uint32_t np = 1; VkPhysicalDevice pd; enumPD(inst, &np, &pd);
  MemProps mp; memprops(pd, &mp);
  float prio = 1.0f; QueueInfo qi = {2, NULL, 0, 0, 1, &prio};
  DevInfo di = {3, NULL, 0, 1, &qi, 0, NULL, 0, NULL, NULL};
  VkDevice dev; if (createDev(pd, &di, NULL, &dev)) return 1;
  VkResult (*alloc)(VkDevice, const AllocInfo *, const void *, VkDeviceMemory *) = (void *)gdpa(dev, "vkAllocateMemory");
  void (*freem)(VkDevice, VkDeviceMemory, const void *) = (void *)gdpa(dev, "vkFreeMemory");
  VkResult (*map)(VkDevice, VkDeviceMemory, uint64_t, uint64_t, uint32_t, void **) = (void *)gdpa(dev, "vkMapMemory");
  for (uint32_t t = 0; t < mp.ntypes; t++) printf("vkmem type %u flags 0x%x heap %u (%llu MB, flags 0x%x)\n", t, mp.types[t].flags, mp.types[t].heap, (unsigned long long)(mp.heaps[mp.types[t].heap].size >> 20), mp.heaps[mp.types[t].heap].flags);
  for (uint32_t t = 0; t < mp.ntypes; t++) {
    if (!(mp.types[t].flags & 2)) continue;  // host visible only
    for (int th = 1; th <= threads; th += threads - 1) {
      double a = now(); AllocInfo ai = {5, NULL, size, t}; VkDeviceMemory m;
      if (alloc(dev, &ai, NULL, &m)) { printf("vkmem type %u: allocation failed\n", t); break; }
      double b = now(); void *p; map(dev, m, 0, size, 0, &p); double c = now();
      double touch = run(p, size, 0, th), retouch = run(p, size, 0, th), rd = run(p, size, 1, th), wr = run(p, size, 2, th);
      double d = now(); freem(dev, m, NULL); double e = now();
      printf("vkmem type %u flags 0x%x, %d threads, 133 MB: allocate %.2f ms, map %.2f, first touch %.2f, second touch %.2f, read all %.2f (%.1f GB/s), write all %.2f (%.1f GB/s), free %.2f\n",
             t, mp.types[t].flags, th, b - a, c - b, touch, retouch, rd, size / rd / 1e6, wr, size / wr / 1e6, e - d);
      if (threads == 1) break;
    }
  }
  // Plain anonymous memory for comparison.
  for (int th = 1; th <= threads; th += threads - 1) {
    unsigned char *p = malloc(size); double touch = run(p, size, 2, th), rd = run(p, size, 1, th);
    printf("vkmem malloc, %d threads: first write %.2f ms, read all %.2f ms\n", th, touch, rd); free(p);
    if (threads == 1) break;
  }
  return 0;
}
