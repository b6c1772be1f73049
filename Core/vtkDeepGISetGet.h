/**
 * Setter macros of the DeepGI classes. vtkDeepGISetClampMacro is VTK's
 * vtkSetClampMacro for floating-point values that also refuses NaN: VTK
 * 9.1's macro clamps with comparisons, which NaN passes unchanged (so a
 * NaN would be stored as the value). NaN keeps the current value and
 * warns; values outside [min, max] are clamped as VTK clamps them.
 */
#ifndef vtkDeepGISetGet_h
#define vtkDeepGISetGet_h

#include "vtkSetGet.h"

#include <cmath> // for std::isnan

#define vtkDeepGISetClampMacro(name, type, min, max)                                               \
  virtual void Set##name(type _arg)                                                                \
  {                                                                                                \
    if (std::isnan(_arg))                                                                          \
    {                                                                                              \
      vtkWarningMacro("Set" #name "(NaN) ignored; " #name " stays " << this->name << ".");         \
      return;                                                                                      \
    }                                                                                              \
    const type clamped = (_arg < min ? min : (_arg > max ? max : _arg));                           \
    if (this->name != clamped)                                                                     \
    {                                                                                              \
      this->name = clamped;                                                                        \
      this->Modified();                                                                            \
    }                                                                                              \
  }                                                                                                \
  virtual type Get##name##MinValue()                                                               \
  {                                                                                                \
    return min;                                                                                    \
  }                                                                                                \
  virtual type Get##name##MaxValue()                                                               \
  {                                                                                                \
    return max;                                                                                    \
  }

#endif
