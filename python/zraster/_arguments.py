"""One-line TypeErrors for calls that match no signature of a compiled function.

pybind11 answers an unknown keyword or an argument of the wrong type with every signature of
the function and a dump of the call, arrays included, over many lines. These wrappers say it as
Python does for its own functions: ``look_at() got an unexpected keyword argument 'width'``, or
the first parameter whose value has the wrong type.
"""

import functools
import re

_INCOMPATIBLE = re.compile(r"^(\w+)\(\): incompatible (?:function|constructor) arguments")
_PARAMETER = re.compile(r"(?:\(|, )(\w+): ([\w.]+)(?: = [^,()]*(?:\([^()]*\))?)?")
_TYPES = {"bool": bool, "str": str, "int": int, "float": (int, float)}


def _parameters(message):
    """[(name, annotation)] of the first signature the message lists."""
    for line in message.splitlines():
        if line.lstrip().startswith("1. "):
            return [(n, t) for n, t in _PARAMETER.findall(line) if n != "self"]
    return []


def _one_line(name, message, args, kwargs):
    parameters = _parameters(message)
    names = [n for n, _ in parameters]
    unknown = [k for k in kwargs if k not in names]
    if unknown:
        listed = ", ".join(repr(k) for k in unknown)
        return (f"{name}() got an unexpected keyword argument{'s' if len(unknown) > 1 else ''} "
                f"{listed} (it takes {', '.join(names)})")
    if len(args) > len(names):
        return f"{name}() takes at most {len(names)} arguments ({', '.join(names)}), got {len(args)}"
    given = dict(zip(names, args), **kwargs)
    for parameter, annotation in parameters:
        expected = _TYPES.get(annotation)
        if parameter in given and expected and not isinstance(given[parameter], expected):
            return (f"{name}(): {parameter} must be {annotation}, not "
                    f"{type(given[parameter]).__name__}")
    missing = [n for n in names if n not in given]
    if missing:
        return f"{name}() missing argument '{missing[0]}' (it takes {', '.join(names)})"
    return message.splitlines()[0]


def one_line_type_errors(function, name=None, method=False):
    """`function`, raising one-line TypeErrors when a call matches none of its signatures
    (`method`: its first argument is self, not one of the parameters the message lists)."""

    @functools.wraps(function)
    def wrapper(*args, **kwargs):
        try:
            return function(*args, **kwargs)
        except BaseException as error:
            match = _INCOMPATIBLE.match(str(error)) if isinstance(error, TypeError) else None
            message = match and _one_line(name or match.group(1), str(error),
                                          args[1:] if method else args, kwargs)
            # An __init__ that raised leaves its object unmade: no traceback may hold it (a
            # repr of it would read memory that was never set).
            del args, kwargs
            if not message:
                raise
            raise TypeError(message) from None

    return wrapper


def wrap_class(cls):
    """Every public method, static method and __init__ of a compiled class, wrapped in place."""
    for attribute, value in list(vars(cls).items()):
        if attribute.startswith("_") and attribute != "__init__":
            continue
        if isinstance(value, staticmethod):
            setattr(cls, attribute, staticmethod(one_line_type_errors(value.__func__)))
        elif type(value).__name__ == "instancemethod":
            shown = cls.__name__ if attribute == "__init__" else None
            setattr(cls, attribute,
                    one_line_type_errors(getattr(cls, attribute), shown, method=True))
    return cls
