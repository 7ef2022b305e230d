package org.stagecraft.player.msg;

import static org.stagecraft.player.wire.MessageType.REQ;
import static org.stagecraft.player.wire.MessageType.SYNCH;

import java.util.List;

import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.player.codec.FieldVisitor;
import org.stagecraft.player.codec.MessageBody;
import org.stagecraft.player.msg.Geometry.DevAddr;
import org.stagecraft.player.xdr.XdrReader;
import org.stagecraft.player.xdr.XdrWriter;

/** Interface 1, "player": the server itself (001_player.def). */
public final class PlayerDevice {
    public static final int CODE = 1;
    public static final int ACCESS_OPEN = 1;
    public static final int ACCESS_CLOSE = 2;
    public static final int ACCESS_ERROR = 3;
    public static final int DATAMODE_PUSH = 1;
    public static final int DATAMODE_PULL = 2;

    private PlayerDevice() {
    }

    static void register(CodecRegistry r) {
        r.registerInterface(CODE, "player");
        r.register(CODE, REQ, 1, "DEVLIST", DevList::read);
        r.register(CODE, REQ, 2, "DRIVERINFO", DriverInfo::read);
        r.register(CODE, REQ, 3, "DEV", DeviceReq::read);
        r.registerEmpty(CODE, REQ, 4, "DATA");
        r.register(CODE, REQ, 5, "DATAMODE", DataMode::read);
        r.register(CODE, REQ, 7, "AUTH", AuthReq::read);
        r.register(CODE, REQ, 8, "NAMESERVICE", NameServiceReq::read);
        r.register(CODE, REQ, 10, "ADD_REPLACE_RULE", ReplaceRule::read);
        r.registerEmpty(CODE, SYNCH, 1, "OK");
        r.register(CODE, SYNCH, 2, "OVERFLOW", SynchOverflow::read);
    }

    /** player_device_devlist: the devices a server offers. */
    public record DevList(int devicesCount, List<DevAddr> devices) implements MessageBody {
        static DevList read(XdrReader r) {
            return new DevList(r.uint32(), Xdr.structs(r, DevAddr.XDR_SIZE, DevAddr::read));
        }

        @Override
        public void encode(XdrWriter w) {
            w.uint32(devicesCount);
            Xdr.structs(w, devices);
        }

        @Override
        public void describe(FieldVisitor v) {
            Xdr.u32(v, "devices_count", devicesCount);
            Xdr.structs(v, "devices", devices);
        }
    }

    /** player_device_driverinfo: the driver behind a device. */
    public record DriverInfo(DevAddr addr, int driverNameCount, ByteArray driverName) implements MessageBody {
        static DriverInfo read(XdrReader r) {
            return new DriverInfo(DevAddr.read(r), r.uint32(), Xdr.bytes(r));
        }

        @Override
        public void encode(XdrWriter w) {
            addr.encode(w);
            w.uint32(driverNameCount);
            Xdr.bytes(w, driverName);
        }

        @Override
        public void describe(FieldVisitor v) {
            Xdr.struct(v, "addr", addr);
            Xdr.u32(v, "driver_name_count", driverNameCount);
            Xdr.text(v, "driver_name", driverName);
        }
    }

    /** player_device_req: subscribe (access 1), unsubscribe (2); replies carry the granted access. */
    public record DeviceReq(DevAddr addr, int access, int driverNameCount, ByteArray driverName) implements MessageBody {
        static DeviceReq read(XdrReader r) {
            return new DeviceReq(DevAddr.read(r), r.uint8(), r.uint32(), Xdr.bytes(r));
        }

        @Override
        public void encode(XdrWriter w) {
            addr.encode(w);
            w.uint8(access).uint32(driverNameCount);
            Xdr.bytes(w, driverName);
        }

        @Override
        public void describe(FieldVisitor v) {
            Xdr.struct(v, "addr", addr);
            v.integer("access", access);
            Xdr.u32(v, "driver_name_count", driverNameCount);
            Xdr.text(v, "driver_name", driverName);
        }
    }

    /** player_device_datamode_req: PUSH (1) or PULL (2). */
    public record DataMode(int mode) implements MessageBody {
        static DataMode read(XdrReader r) {
            return new DataMode(r.uint8());
        }

        @Override
        public void encode(XdrWriter w) {
            w.uint8(mode);
        }

        @Override
        public void describe(FieldVisitor v) {
            v.integer("mode", mode);
        }
    }

    /** player_device_auth_req. */
    public record AuthReq(int authKeyCount, ByteArray authKey) implements MessageBody {
        static AuthReq read(XdrReader r) {
            return new AuthReq(r.uint32(), Xdr.bytes(r));
        }

        @Override
        public void encode(XdrWriter w) {
            w.uint32(authKeyCount);
            Xdr.bytes(w, authKey);
        }

        @Override
        public void describe(FieldVisitor v) {
            Xdr.u32(v, "auth_key_count", authKeyCount);
            v.opaque("auth_key", authKey.toArray());
        }
    }

    /** player_device_nameservice_req. */
    public record NameServiceReq(int nameCount, ByteArray name, int port) implements MessageBody {
        static NameServiceReq read(XdrReader r) {
            return new NameServiceReq(r.uint32(), Xdr.bytes(r), r.uint16());
        }

        @Override
        public void encode(XdrWriter w) {
            w.uint32(nameCount);
            Xdr.bytes(w, name);
            w.uint16(port);
        }

        @Override
        public void describe(FieldVisitor v) {
            Xdr.u32(v, "name_count", nameCount);
            Xdr.text(v, "name", name);
            v.integer("port", port);
        }
    }

    /** player_add_replace_rule_req; -1 is a wildcard. */
    public record ReplaceRule(int interf, int index, int type, int subtype, int replace) implements MessageBody {
        static ReplaceRule read(XdrReader r) {
            return new ReplaceRule(r.int32(), r.int32(), r.int32(), r.int32(), r.int32());
        }

        @Override
        public void encode(XdrWriter w) {
            w.int32(interf).int32(index).int32(type).int32(subtype).int32(replace);
        }

        @Override
        public void describe(FieldVisitor v) {
            v.integer("interf", interf);
            v.integer("index", index);
            v.integer("type", type);
            v.integer("subtype", subtype);
            v.integer("replace", replace);
        }
    }

    /** SYNCH OVERFLOW: player_uint32, the number of messages the server dropped. */
    public record SynchOverflow(int data) implements MessageBody {
        static SynchOverflow read(XdrReader r) {
            return new SynchOverflow(r.uint32());
        }

        @Override
        public void encode(XdrWriter w) {
            w.uint32(data);
        }

        @Override
        public void describe(FieldVisitor v) {
            Xdr.u32(v, "data", data);
        }
    }
}
