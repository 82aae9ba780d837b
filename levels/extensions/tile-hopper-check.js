/*
 * Tile Hopper: check the open map and list what the checker finds in Tiled's Issues panel.
 *
 * Tiled loads this file when the project in levels/ is open (its "extensionsPath" is
 * "extensions") and its extensions are enabled. It adds "Check Tile Hopper Map"
 * (Ctrl+Shift+F6) to the Map menu. The action saves the map, runs
 *     python -I -m game.levels check --format json --budget 1000 -- MAP
 * (Tiled's Process API, Tiled 1.8) and turns each finding into an entry of the Issues
 * panel: errors with tiled.error, warnings and "not decided" with tiled.warn. Activating an
 * entry selects the object it names (object #ID) or else the tile it names (tile (X,Y)) and
 * centres the view there.
 *
 * Tiled 1.8's scripts can add to the Issues panel (tiled.warn, tiled.error) but not remove
 * from it: the tiled module has log, warn and error, and no way to clear the panel (only
 * its Clear button does). So each check starts with a separator line in the Console, and an
 * entry of an earlier check of the same map that this check did not find again selects
 * nothing when activated: it says so in the Console instead (an entry found again is the
 * same entry in Tiled's panel, which then runs the newest check's selection).
 *
 * A map may come from anyone, so nothing of its folder runs: Python starts in isolated mode
 * (-I: neither the working folder nor PYTHON* variables nor the user's site-packages reach
 * sys.path, so a game/ package or an argparse.py beside the map is never imported), in
 * Tiled's own folder, with the map's path as one argument after "--". Only a Python with the
 * game installed (pip install -e .) is used. The check writes nothing.
 *
 * Tiled's interface waits while the check runs, so the search for a route is bounded by
 * work: SEARCH_BUDGET moves, which answers in a few seconds even on the busiest map the
 * game's limits allow. A map the search does not decide within it gets a "not decided"
 * warning; F6 (Check this level) runs the full search without making Tiled wait.
 */
/* global tiled, Process, Qt */

var PYTHONS = tiled.platform === "windows" ? ["python.exe", "py.exe"] : ["python3", "python"];
var SEARCH_BUDGET = 1000;  // moves the search may try: about 1 s on a shipped level, about
                           // 10 s of CPU on the busiest map the limits allow
var NOT_INSTALLED = /No module named '?game\b/;  // Python's words when the game is not installed
var SHOWN_CHARS = 2000;  // the most of a message the Issues panel is given
var checks = 0;  // checks run since Tiled loaded this extension
var latestCheckOf = {};  // map file -> the number of its latest check

function checkerArguments(mapFile) {
    return ["-I", "-m", "game.levels", "check", "--format", "json",
            "--budget", String(SEARCH_BUDGET), "--", mapFile];
}

function escapedChar(c) {
    var code = c.charCodeAt(0);
    if (c === "\n") return "\\n";
    if (c === "\r") return "\\r";
    if (c === "\t") return "\\t";
    var hex = code.toString(16);
    return code <= 0xff ? "\\x" + ("0" + hex).slice(-2) : "\\u" + ("000" + hex).slice(-4);
}

// Controls (C0, C1), bidi marks, embeddings, overrides and isolates, zero-width and other
// format characters, line and paragraph separators and the byte order mark.
var UNSAFE = new RegExp("[\\u0000-\\u001f\\u007f-\\u009f\\u00ad\\u061c\\u180e" +
                        "\\u200b-\\u200f\\u2028-\\u202e\\u2060-\\u206f\\ufeff]", "g");

function shown(text) {
    // What Tiled's panels may show: every character that could hide, reorder or split
    // the text written as an escape, and at most SHOWN_CHARS of it.
    var plain = String(text);
    if (plain.length > SHOWN_CHARS)
        plain = plain.slice(0, SHOWN_CHARS) + "... (" + plain.length + " characters)";
    return plain.replace(UNSAFE, escapedChar);
}

function findObject(layers, id) {
    for (var i = 0; i < layers.length; ++i) {
        var layer = layers[i];
        if (layer.isObjectLayer) {
            var objects = layer.objects;
            for (var j = 0; j < objects.length; ++j) {
                if (objects[j].id === id)
                    return objects[j];
            }
        }
        if (layer.isGroupLayer) {
            var found = findObject(layer.layers, id);
            if (found)
                return found;
        }
    }
    return null;
}

function centreOn(map, x, y) {
    var view = tiled.mapEditor && tiled.mapEditor.currentMapView;
    if (tiled.activeAsset === map && view && typeof view.centerOn === "function")
        view.centerOn(x, y);
}

function selectTile(map, tile) {
    var x = tile[0], y = tile[1];
    if (map.selectedArea && typeof map.selectedArea.set === "function")
        map.selectedArea.set(Qt.rect(x, y, 1, 1));
    centreOn(map, (x + 0.5) * map.tileWidth, (y + 0.5) * map.tileHeight);
}

function selector(map, finding, check) {
    var mapFile = map.fileName;
    return function () {
        if (latestCheckOf[mapFile] !== check) {
            tiled.log(shown("Tile Hopper: this finding is from an earlier check of " + mapFile +
                            " and the latest check did not find it again; press Clear in " +
                            "the Issues panel to remove the findings of earlier checks"));
            return;
        }
        if (tiled.activeAsset !== map)
            tiled.activeAsset = map;
        var object = typeof finding.object_id === "number"
            ? findObject(map.layers, finding.object_id) : null;
        if (object) {
            map.selectedObjects = [object];
            centreOn(map, object.x + object.width / 2, object.y + object.height / 2);
        } else if (Array.isArray(finding.tile)) {
            selectTile(map, finding.tile);
        }
    };
}

function runCheck(mapFile) {
    // The first Python on the PATH with the game installed; null if none has it.
    var tried = [];
    for (var i = 0; i < PYTHONS.length; ++i) {
        var process = new Process();
        process.workingDirectory = tiled.applicationDirPath;  // never the map's folder
        var status = process.exec(PYTHONS[i], checkerArguments(mapFile), false);
        var out = process.readStdOut();
        var err = process.readStdErr();
        process.close();
        if (status < 0)
            continue;  // no such program
        if (out.length === 0 && NOT_INSTALLED.test(err)) {
            tried.push(PYTHONS[i]);
            continue;
        }
        return { status: status, out: out, err: err, python: PYTHONS[i] };
    }
    return { status: -1, out: "", err: "", tried: tried };
}

var checkAction = tiled.registerAction("TileHopperCheck", function () {
    var map = tiled.activeAsset;
    if (!map || !map.isTileMap) {
        tiled.alert("Open a map first.", "Check Tile Hopper Map");
        return;
    }
    if (map.modified)
        tiled.trigger("Save");
    var mapFile = map.fileName;
    checks += 1;
    latestCheckOf[mapFile] = checks;
    tiled.log(shown("==== Tile Hopper check " + checks + ": " + mapFile + " ==== (the " +
                    "Issues panel keeps the findings of earlier checks until you press its " +
                    "Clear button)"));
    tiled.log(shown("Checking " + mapFile + " (reading it, then searching for a route " +
                    "of at most " + SEARCH_BUDGET + " moves)..."));
    var result = runCheck(mapFile);
    if (result.status < 0) {
        tiled.error(result.tried.length === 0
            ? "Tile Hopper: Python was not found; start Tiled from a shell where the game's " +
              "Python is active"
            : "Tile Hopper: the game is not installed for " + result.tried.join(" or ") +
              "; run pip install -e . in the game's folder, or start Tiled from a shell " +
              "where the game's Python is active", function () {});
        return;
    }
    var report;
    try {
        report = JSON.parse(result.out);
    } catch (error) {
        tiled.error(shown("Tile Hopper: the checker (" + result.python + ") did not answer " +
                          "in JSON (exit status " + result.status + "): " +
                          result.err.trim()), function () {});
        return;
    }
    report.maps.forEach(function (checked) {
        checked.findings.forEach(function (finding) {
            var text = shown(finding.text);
            if (finding.severity === "error")
                tiled.error(text, selector(map, finding, checks));
            else
                tiled.warn(text, selector(map, finding, checks));
        });
    });
    tiled.log(shown(report.summary));
});
checkAction.text = "Check Tile Hopper Map";
checkAction.shortcut = "Ctrl+Shift+F6";

tiled.extendMenu("Map", [
    { separator: true },
    { action: "TileHopperCheck" }
]);
