"""Errors a robot program can meet, each naming the server, the device and what happened."""

from __future__ import annotations


class PlayerError(Exception):
    """Base class of every error this library raises."""


class PlayerConnectionError(PlayerError, ConnectionError):
    """The server cannot be reached, is not a Player server, or went away."""


class ConnectionLost(PlayerConnectionError):
    """The server closed the connection (Player stopped or crashed)."""


class PlayerTimeout(PlayerError, TimeoutError):
    """No reply (or no data) within the time allowed."""


class PlayerProtocolError(PlayerError):
    """Bytes that are not a well-formed Player message or payload."""


class RequestRefused(PlayerError):
    """The server answered a request with RESP_NACK (the driver does not support it, or failed)."""

    def __init__(self, message: str, *, body: bytes = b"") -> None:
        super().__init__(message)
        self.body = body


class DeviceRefused(RequestRefused):
    """Subscribing to (or unsubscribing from) a device was refused: it does not exist or failed."""


class WrongInterface(PlayerError, ValueError):
    """A device address names another interface than the proxy it was given to."""


class UnitError(PlayerError, ValueError):
    """A quantity has the wrong dimension for what it is given as (e.g. metres for an angular speed)."""
