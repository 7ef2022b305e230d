"""What every device proxy shares: its address, subscription, data dispatch, requests, properties."""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING, Any, ClassVar

from .errors import WrongInterface
from .wire import INTERFACES, DeviceAddress, Header
from .xdr import XdrReader, XdrWriter

if TYPE_CHECKING:
    from .client import Client, Reply

# Requests every interface may answer (player.h).
REQ_GET_INTPROP = 254
REQ_SET_INTPROP = 253
REQ_GET_DBLPROP = 252
REQ_SET_DBLPROP = 251
REQ_GET_STRPROP = 250
REQ_SET_STRPROP = 249
REQ_GET_BOOLPROP = 248
REQ_SET_BOOLPROP = 247


class Proxy:
    """A local copy of one device: the latest data, plus its commands and requests.

    ``device`` is an index (``0``) or an address (``"laser:0"``); an address of another interface
    raises :class:`WrongInterface`. The proxy subscribes on creation unless ``subscribe=False``.
    After each :meth:`Client.read`, ``fresh`` tells whether new data came for this device.
    """

    INTERFACE: ClassVar[str] = ""
    #: DATA subtypes this proxy decodes: subtype -> payload reader.
    DATA: ClassVar[dict[int, Callable[[XdrReader], Any]]] = {}

    def __init__(self, client: Client, device: int | str = 0, *, subscribe: bool = True) -> None:
        self.client = client
        self.address = self._resolve(device)
        self.driver: str | None = None
        self.fresh = False
        self.timestamp = 0.0
        client._attach(self)
        if subscribe:
            self.subscribe()

    @classmethod
    def _resolve(cls, device: int | str) -> DeviceAddress:
        code = INTERFACES[cls.INTERFACE]
        if isinstance(device, bool) or not isinstance(device, (int, str)):
            raise TypeError(f"{cls.__name__}: device must be an index or an address like "
                            f"'{cls.INTERFACE}:0', not {device!r}")
        if isinstance(device, int):
            return DeviceAddress(code, device)
        address = DeviceAddress.parse(device)
        if address.interf != code:
            raise WrongInterface(f"{cls.__name__} reads '{cls.INTERFACE}' devices, but '{device}' is a "
                                 f"'{address.interface}' device (use the {address.interface} proxy)")
        return address

    @property
    def index(self) -> int:
        return self.address.index

    def subscribe(self) -> None:
        self.driver = self.client.subscribe(self.address)

    def unsubscribe(self) -> None:
        self.client.unsubscribe(self.address)
        self.driver = None

    def __repr__(self) -> str:
        return f"<{type(self).__name__} {self.address} on {self.client.host}:{self.client.port}>"

    # -- data ---------------------------------------------------------------------------------

    def _on_data(self, header: Header, body: bytes) -> Any:
        read = self.DATA.get(header.subtype)
        if read is None:
            return body
        reader = XdrReader(body, f"{self.address} DATA subtype {header.subtype}")
        record = read(reader)
        self.timestamp = header.timestamp
        self.fresh = True
        self._take(header.subtype, record)
        return record

    def _take(self, subtype: int, record: Any) -> None:
        """Stores a decoded record in the proxy's fields (each proxy knows its own)."""

    # -- requests -----------------------------------------------------------------------------

    def _request(self, subtype: int, body: bytes = b"", timeout: float | None = None) -> Reply:
        return self.client.request(self.address.interf, self.address.index, subtype, body, timeout=timeout)

    def _reader(self, reply: Reply, what: str) -> XdrReader:
        return XdrReader(reply.body, f"{self.address} {what} reply")

    def _command(self, subtype: int, body: bytes) -> None:
        self.client.command(self.address.interf, self.address.index, subtype, body)

    # -- properties (any interface; drivers decide which keys exist) ---------------------------

    def get_int_property(self, key: str) -> int:
        reply = self._request(REQ_GET_INTPROP, XdrWriter().string(key).int32(0).to_bytes())
        r = self._reader(reply, "GET_INTPROP")
        r.string()
        return r.int32()

    def set_int_property(self, key: str, value: int) -> None:
        self._request(REQ_SET_INTPROP, XdrWriter().string(key).int32(value).to_bytes())

    def get_double_property(self, key: str) -> float:
        reply = self._request(REQ_GET_DBLPROP, XdrWriter().string(key).float64(0.0).to_bytes())
        r = self._reader(reply, "GET_DBLPROP")
        r.string()
        return r.float64()

    def set_double_property(self, key: str, value: float) -> None:
        self._request(REQ_SET_DBLPROP, XdrWriter().string(key).float64(value).to_bytes())

    def get_string_property(self, key: str) -> str:
        reply = self._request(REQ_GET_STRPROP, XdrWriter().string(key).counted_bytes(b"").to_bytes())
        r = self._reader(reply, "GET_STRPROP")
        r.string()
        return r.string()

    def set_string_property(self, key: str, value: str) -> None:
        self._request(REQ_SET_STRPROP, XdrWriter().string(key).string(value).to_bytes())

    def get_bool_property(self, key: str) -> bool:
        reply = self._request(REQ_GET_BOOLPROP, XdrWriter().string(key).int32(0).to_bytes())
        r = self._reader(reply, "GET_BOOLPROP")
        r.string()
        return r.int32() != 0

    def set_bool_property(self, key: str, value: bool) -> None:
        self._request(REQ_SET_BOOLPROP, XdrWriter().string(key).int32(int(value)).to_bytes())
