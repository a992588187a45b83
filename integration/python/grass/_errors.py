"""The exceptions of the Pythonic layer. Every failure is a GrassError: one the library
reported (its result, message id and sentence), one the binding found before calling it (an
argument of the wrong type or range: ArgumentError, also a ValueError and a TypeError), a
closed context or object (ClosedError), or a Python callback that raised (the exception is
the GrassError's __cause__)."""
from enum import IntEnum

from ._ffi import ENUMS

Result = IntEnum("Result", ENUMS["grass_result"])
MessageId = IntEnum("MessageId", ENUMS["grass_message_id"])


class GrassError(Exception):
    """A grass call that did not succeed: result (Result), message_id (MessageId of the error
    the call logged, GRASS_MSG_NONE when there is none) and message."""

    def __init__(self, result, message_id=0, message=""):
        self.result = Result(result)
        try:
            self.message_id = MessageId(message_id)
        except ValueError:  # an id newer than this binding
            self.message_id = message_id
        self.message = message
        super().__init__(f"{self.result.name} ({getattr(self.message_id, 'name', message_id)}): {message}")


class ArgumentError(GrassError, ValueError, TypeError):
    """An argument the binding refused before calling the library (GRASS_ERROR_INVALID_ARGUMENT)."""

    def __init__(self, message, message_id=ENUMS["grass_message_id"]["GRASS_MSG_NONE"]):
        super().__init__(ENUMS["grass_result"]["GRASS_ERROR_INVALID_ARGUMENT"], message_id, message)


class ClosedError(GrassError):
    """A call on a destroyed context or object (GRASS_ERROR_INVALID_HANDLE)."""

    def __init__(self, message):
        super().__init__(ENUMS["grass_result"]["GRASS_ERROR_INVALID_HANDLE"],
                         ENUMS["grass_message_id"]["GRASS_MSG_STALE_HANDLE"], message)


def short(value, limit=60):
    """repr(value), cut to `limit` characters."""
    text = repr(value)
    return text if len(text) <= limit else text[:limit - 3] + "..."
