package org.stagecraft.tools.cfg;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.stagecraft.tools.session.Worlds;

/** Reading Player cfg files: address forms, ports, layout, includes, and errors that say where. */
class PlayerCfgTest {
    @TempDir
    Path tmp;

    private Path write(String name, String text) throws IOException {
        Path p = tmp.resolve(name);
        Files.createDirectories(p.getParent());
        Files.writeString(p, text);
        return p;
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
            "position2d:0                |          |            | -1   | position2d | 0",
            "6666:position2d:0           |          |            | 6666 | position2d | 0",
            "localhost:6666:position2d:0 |          | localhost  | 6666 | position2d | 0",
            "odometry:::position2d:0     | odometry |            | -1   | position2d | 0",
            "odometry::6667:position2d:1 | odometry |            | 6667 | position2d | 1",
            "key:robot7:6670:laser:2     | key      | robot7     | 6670 | laser      | 2",
            ":6668:ranger:1              |          |            | 6668 | ranger     | 1" })
    void everyAddressFormPlayerAccepts(String text, String key, String host, int port, String iface, int index) {
        DeviceAddress a = DeviceAddress.parse(text.trim());
        assertEquals(key == null ? "" : key, a.key());
        assertEquals(host == null ? "" : host, a.host());
        assertEquals(port, a.port());
        assertEquals(iface, a.iface());
        assertEquals(index, a.index());
        // moving the port keeps key, host, interface and index
        DeviceAddress moved = DeviceAddress.parse(a.withPort(40001));
        assertEquals(new DeviceAddress(a.key(), a.host(), 40001, iface, index), moved);
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
            "position2d              | not a device address",
            "a:b:c:d:e:f             | not a device address",
            "70000:laser:0           | not 1..65535",
            "abc:laser:0             | not a number",
            "6665:laser:x            | not a number",
            "6665::0                 | no valid interface" })
    void badAddressesSayWhatIsWrong(String text, String expected) {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> DeviceAddress.parse(text.trim()));
        assertTrue(e.getMessage().contains(expected), e.getMessage());
        assertTrue(e.getMessage().contains(text.trim()), e.getMessage());
    }

    @Test
    void oneRobotUsesTheDefaultPort() throws Exception {
        PlayerCfg cfg = PlayerCfg.read(Worlds.file("pioneer-laser-sonar.cfg"));
        assertEquals(6, cfg.addresses().size());
        assertEquals(5, cfg.addresses().stream().filter(a -> a.role() == PlayerCfg.Role.PROVIDES).count());
        assertTrue(cfg.usesDefaultPort());
        assertEquals(List.of(6665), List.copyOf(cfg.listenPorts(6665).keySet()));
        assertEquals(List.of(7000), List.copyOf(cfg.listenPorts(7000).keySet()));
        PlayerCfg.AddressUse first = cfg.listenPorts(6665).get(6665);
        assertEquals("simulation:0", first.token().text());
        assertEquals(6, first.token().line());
        assertEquals("stage", first.driver());
    }

    @Test
    void sixRobotsOnSixPortsAreAllMovedIncludingRequires() throws Exception {
        Path original = Worlds.file("six-robots.cfg");
        PlayerCfg cfg = PlayerCfg.read(original);
        assertFalse(cfg.usesDefaultPort());
        assertEquals(List.of(7665, 7666, 7667, 7668, 7669, 7670), List.copyOf(cfg.listenPorts(6665).keySet()));
        Map<Integer, Integer> map = new LinkedHashMap<>();
        for (int i = 0; i < 6; i++) {
            map.put(7665 + i, 41000 + i * 7);
        }
        Path out = Files.createDirectories(tmp.resolve("scratch"));
        CfgRewriter.Rewritten r = CfgRewriter.write(cfg, map, out);
        assertEquals(out.resolve("six-robots.cfg"), r.main());

        PlayerCfg copy = PlayerCfg.read(r.main());
        assertEquals(List.copyOf(map.values()), List.copyOf(copy.listenPorts(6665).keySet()));
        assertEquals(cfg.addresses().size(), copy.addresses().size());
        for (int i = 0; i < cfg.addresses().size(); i++) {
            DeviceAddress before = cfg.addresses().get(i).address();
            DeviceAddress after = copy.addresses().get(i).address();
            assertEquals(map.get(before.port()), after.port(), "address " + i + " " + before);
            assertEquals(before.iface(), after.iface());
            assertEquals(before.index(), after.index());
            assertEquals(cfg.addresses().get(i).role(), copy.addresses().get(i).role());
            assertEquals(cfg.addresses().get(i).token().line(), copy.addresses().get(i).token().line());
        }
        // 31 addresses with a port + the world file, nothing else
        assertEquals(32, r.changes().size());
        String text = Files.readString(r.main());
        assertTrue(text.contains("# six-robots.cfg -- Player config for six-robots.world"), "comments are kept");
        assertEquals(Files.readAllLines(original).size(), Files.readAllLines(r.main()).size(), "layout is kept");
        Path world = original.getParent().resolve("six-robots.world").toAbsolutePath().normalize();
        assertTrue(text.contains("worldfile \"" + world + "\""), text);
        assertTrue(text.contains("plugin \"stageplugin\""), "a plugin name that is no file stays a name");
        assertTrue(text.contains("model \"r3\""));
        assertFalse(text.contains("\"7665:"), "no original port is left in an address");
        assertTrue(text.contains("BASE = 7665 here"), "but comments are not touched");
    }

    @Test
    void defaultPortAddressesStayAsTheyAreAndTheWorldFileBecomesAbsolute() throws Exception {
        PlayerCfg cfg = PlayerCfg.read(Worlds.file("pioneer-laser-sonar.cfg"));
        CfgRewriter.Rewritten r = CfgRewriter.write(cfg, Map.of(6665, 40123), Files.createDirectories(tmp.resolve("s")));
        assertEquals(1, r.changes().size(), r.changes().toString());
        assertEquals("pioneer-laser-sonar.world", r.changes().get(0).before());
        assertTrue(Files.exists(Path.of(r.changes().get(0).after())));
        assertTrue(Files.readString(r.main()).contains("provides [ \"position2d:0\" \"ranger:0\" \"ranger:1\" ]"));
    }

    @Test
    void layoutCommentsQuotesMultiLineListsAndNestedSections() throws Exception {
        Path world = write("w/simple.world", "# a world\n");
        write("w/libmine.so", "not really a library");
        Path cfgFile = write("w/odd.cfg", """
                # a comment with "quotes" and provides [ "1:x:0" ]
                driver(name "stage" provides ["simulation:0"] plugin "stageplugin" worldfile "simple.world")
                driver
                (
                  name "mine"   # a driver with a relative plugin path
                  plugin "./libmine.so"
                  provides [
                    "odometry:::position2d:0"      # key, empty host and port
                    "6701:laser:0" # hash in a string: "not # a comment"
                    "localhost:6702:sonar:0"
                    "otherhost:6703:ranger:0"
                  ]
                  requires [ "6701:laser:0" "otherhost:6703:ranger:0" ]
                  label "a # inside a string"
                  nested ( size [ 1.0 2.0 ] color "red" )
                )
                """);
        PlayerCfg cfg = PlayerCfg.read(cfgFile);
        assertEquals(List.of(6665, 6701, 6702, 6703), List.copyOf(cfg.listenPorts(6665).keySet()));
        assertEquals(7, cfg.addresses().size());
        assertEquals("mine", cfg.addresses().get(1).driver());
        assertEquals(9, cfg.addresses().get(2).token().line());

        Map<Integer, Integer> map = Map.of(6665, 50000, 6701, 50001, 6702, 50002);
        CfgRewriter.Rewritten r = CfgRewriter.write(cfg, map, Files.createDirectories(tmp.resolve("out")));
        String text = Files.readString(r.main());
        assertTrue(text.contains("\"odometry:::position2d:0\""), "no port: -p moves it");
        assertTrue(text.contains("\"50001:laser:0\" # hash in a string: \"not # a comment\""), text);
        assertTrue(text.contains("\"localhost:50002:sonar:0\""), text);
        assertTrue(text.contains("\"otherhost:6703:ranger:0\""), "another host's Player is not ours to move");
        assertTrue(text.contains("requires [ \"50001:laser:0\" \"otherhost:6703:ranger:0\" ]"), text);
        assertTrue(text.contains("worldfile \"" + world.toAbsolutePath() + "\""), text);
        assertTrue(text.contains("plugin \"" + tmp.resolve("w/libmine.so").toAbsolutePath() + "\""), text);
        assertTrue(text.contains("plugin \"stageplugin\""), text);
        assertTrue(text.contains("color \"red\""), text);
        assertTrue(text.startsWith("# a comment with \"quotes\" and provides [ \"1:x:0\" ]"), "comments untouched");
    }

    @Test
    void includedFilesAreReadRewrittenAndResolvedFromTheirOwnDirectory() throws Exception {
        write("proj/robots/r.world", "");
        write("proj/robots/robots.inc", """
                driver ( name "stage" provides [ "6801:position2d:0" ] worldfile "r.world" )
                """);
        write("proj/main.cfg", """
                include "robots/robots.inc"
                driver ( name "x" provides [ "6800:laser:0" ] requires [ "6801:position2d:0" ] )
                """);
        PlayerCfg cfg = PlayerCfg.read(tmp.resolve("proj/main.cfg"));
        assertEquals(2, cfg.sources().size());
        assertEquals(List.of(6800, 6801), List.copyOf(cfg.listenPorts(6665).keySet()));
        Path out = Files.createDirectories(tmp.resolve("scratch"));
        CfgRewriter.Rewritten r = CfgRewriter.write(cfg, Map.of(6800, 51000, 6801, 51001), out);
        assertEquals(2, r.files().size());
        Path inc = out.resolve("include1-robots.inc");
        assertEquals(inc, r.files().get(1));
        assertTrue(Files.readString(r.main()).contains("include \"" + inc + "\""));
        String incText = Files.readString(inc);
        assertTrue(incText.contains("\"51001:position2d:0\""), incText);
        assertTrue(incText.contains("worldfile \"" + tmp.resolve("proj/robots/r.world").toAbsolutePath() + "\""), incText);
        // the copy is complete in itself: reading it finds the moved ports through the copied include
        assertEquals(List.of(51000, 51001), List.copyOf(PlayerCfg.read(r.main()).listenPorts(6665).keySet()));
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
            "driver ( name \"x\" provides [ \"6665:laser:0\" ] |1|never closed",
            "driver ( name \"x\"\\n provides [ \"6665:laser:0\" \\n)|2|is not closed with ']'",
            "driver ( name \"x\\n provides [ ] )|1|no closing quote",
            "driver ( name \"x\" )\\n)|2|without a section",
            "driver ( name \"x\"\\n\\n provides [ \"70000:laser:0\" ] )|3|provides: '70000:laser:0' has port 70000",
            "driver ( name )|1|has no value",
            "include \"nowhere.inc\"|1|does not exist",
            "driver ( [ ] )|1|expected a name" })
    void badCfgNamesFileAndLine(String text, int line, String expected) throws Exception {
        Path f = write("bad.cfg", text.replace("\\n", "\n"));
        CfgException e = assertThrows(CfgException.class, () -> PlayerCfg.read(f));
        assertEquals(line, e.line(), e.getMessage());
        assertTrue(e.getMessage().startsWith(f.toAbsolutePath() + ":" + line + ": "), e.getMessage());
        assertTrue(e.getMessage().contains(expected), e.getMessage());
    }

    @Test
    void includeCyclesAndMissingFilesAreReported() throws Exception {
        write("a.cfg", "include \"b.cfg\"\n");
        write("b.cfg", "\ninclude \"a.cfg\"\n");
        CfgException cycle = assertThrows(CfgException.class, () -> PlayerCfg.read(tmp.resolve("a.cfg")));
        assertTrue(cycle.getMessage().startsWith(tmp.resolve("b.cfg") + ":2: include cycle"), cycle.getMessage());
        CfgException missing = assertThrows(CfgException.class, () -> PlayerCfg.read(tmp.resolve("none.cfg")));
        assertTrue(missing.getMessage().contains("none.cfg: no such file"), missing.getMessage());
    }
}
