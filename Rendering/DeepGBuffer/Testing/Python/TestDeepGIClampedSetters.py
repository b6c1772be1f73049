"""Every clamped floating-point setter the vtkdeepgi classes declare (found
by its Get<Name>MinValue / Get<Name>MaxValue pair) refuses NaN: the value
stays and one warning is given. Values outside the range are clamped to
it, without a warning, as VTK's clamped setters do."""
import math
import sys

import vtkdeepgi
from vtkmodules.vtkCommonCore import vtkCommand


def clamped_properties(cls):
    # What the class and its vtkdeepgi bases declare (the estimators inherit
    # RelativeOffset from vtkDeepGIReferenceEstimator); inherited VTK setters
    # (e.g. of vtkRenderWindow) keep VTK's own behaviour.
    for base in cls.__mro__:
        if not base.__module__.startswith("vtkdeepgi"):
            break
        for attribute in vars(base):
            if attribute.startswith("Get") and attribute.endswith("MinValue"):
                yield attribute[len("Get"):-len("MinValue")]


def check(obj, name, failures):
    low = getattr(obj, "Get%sMinValue" % name)()
    high = getattr(obj, "Get%sMaxValue" % name)()
    if not isinstance(low, float):
        return False  # an integer setter: NaN cannot reach it
    get, set_ = getattr(obj, "Get" + name), getattr(obj, "Set" + name)
    warnings = []
    tag = obj.AddObserver(vtkCommand.WarningEvent, lambda o, e: warnings.append(e))
    inside = low + 0.5 * min(high - low, 1.0)
    set_(inside)
    set_(float("nan"))
    label = "%s.Set%s" % (obj.GetClassName(), name)
    if get() != inside or len(warnings) != 1:
        failures.append("%s(nan): value %r (expected %r), %d warning(s)"
                        % (label, get(), inside, len(warnings)))
    set_(low - 1.0)
    if get() != low:
        failures.append("%s(%r): %r, expected the minimum %r" % (label, low - 1.0, get(), low))
    if math.isfinite(high):
        set_(high + 1.0)
        if get() != high:
            failures.append("%s(%r): %r, expected the maximum %r" % (label, high + 1.0, get(), high))
    obj.RemoveObserver(tag)
    return True


def main():
    failures = []
    checked = []
    for class_name in sorted(dir(vtkdeepgi)):
        cls = getattr(vtkdeepgi, class_name)
        properties = list(clamped_properties(cls)) if isinstance(cls, type) else []
        if not properties:
            continue
        try:
            obj = cls()
        except TypeError:
            continue  # an abstract base: checked through its subclasses
        for name in properties:
            if check(obj, name, failures):
                checked.append("%s.%s" % (class_name, name))
    print("checked %d clamped floating-point setters: %s" % (len(checked), ", ".join(checked)))
    for failure in failures:
        print("FAILED: " + failure)
    # 18 in the passes and scenes (the vtkDeepGBuffer scene classes' inherited
    # FeatureAngle included), 6 more in the optional DeepGI::Reference (Bias,
    # Epsilon and each estimator's inherited RelativeOffset,
    # DiffuseCoefficient).
    expected = 24 if hasattr(vtkdeepgi, "vtkDeepGIReferenceObscurance") else 18
    if len(checked) < expected:
        failures.append("only %d setters found (%d expected)" % (len(checked), expected))
        print("FAILED: " + failures[-1])
    print("%d failure(s)" % len(failures))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
