/*
 * Tile Hopper: check the open map and list what the checker finds in Tiled's Issues panel.
 *
 * Tiled loads this file when the project in levels/ is open (its "extensionsPath" is
 * "extensions"). It adds "Check Tile Hopper Map" (Ctrl+Shift+F6) to the Map menu. The action
 * saves the map, runs `python -m game.levels check --format json MAP` in the folder above
 * levels/ (Tiled's Process API, Tiled 1.8), and turns each finding into an entry of the
 * Issues panel: errors with tiled.error, warnings and "not decided" with tiled.warn.
 * Activating an entry selects the object it names (object #ID) or the tile it names
 * (tile (X,Y)) and centres the view there.
 *
 * Tiled's interface waits while the check runs (a search for a route can take seconds);
 * the Console says when it starts and how it ended.
 */

/* global tiled, Process, Qt */

var PYTHONS = tiled.platform === "windows" ? ["python.exe", "py.exe"] : ["python3", "python"];

function projectFolder(mapFile) {
    // The map is somewhere below levels/; the game is run from the folder above levels/.
    var parts = mapFile.split("/");
    var levels = parts.lastIndexOf("levels");
    if (levels <= 0)
        return parts.slice(0, -1).join("/");
    return parts.slice(0, levels).join("/");
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

function selector(map, finding) {
    return function () {
        if (tiled.activeAsset !== map)
            tiled.activeAsset = map;
        if (finding.object_id !== null) {
            var object = findObject(map.layers, finding.object_id);
            if (object) {
                map.selectedObjects = [object];
                centreOn(map, object.x + object.width / 2, object.y + object.height / 2);
            }
        } else if (finding.tile !== null) {
            var x = finding.tile[0], y = finding.tile[1];
            if (map.selectedArea && typeof map.selectedArea.set === "function")
                map.selectedArea.set(Qt.rect(x, y, 1, 1));
            centreOn(map, (x + 0.5) * map.tileWidth, (y + 0.5) * map.tileHeight);
        }
    };
}

function runCheck(mapFile, folder) {
    for (var i = 0; i < PYTHONS.length; ++i) {
        var process = new Process();
        process.workingDirectory = folder;
        var status = process.exec(PYTHONS[i], ["-m", "game.levels", "check", "--format",
                                               "json", mapFile], false);
        var out = process.readStdOut();
        var err = process.readStdErr();
        process.close();
        if (status >= 0 && out.length > 0)
            return { status: status, out: out, err: err };
        if (status >= 0)  // Python ran but printed nothing: usage or a crash
            return { status: status, out: "", err: err };
    }
    return null;
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
    tiled.log("Checking " + mapFile + " (reading it, then searching for a route)...");
    var result = runCheck(mapFile, projectFolder(mapFile));
    if (result === null) {
        tiled.error("Tile Hopper: Python was not found; start Tiled from a shell where the " +
                    "game's Python is active", function () {});
        return;
    }
    var report;
    try {
        report = JSON.parse(result.out);
    } catch (error) {
        tiled.error("Tile Hopper: the checker did not answer in JSON (exit status " +
                    result.status + "): " + result.err.trim(), function () {});
        return;
    }
    report.maps.forEach(function (checked) {
        checked.findings.forEach(function (finding) {
            var text = finding.text;
            if (finding.severity === "error")
                tiled.error(text, selector(map, finding));
            else
                tiled.warn(text, selector(map, finding));
        });
    });
    tiled.log(report.summary);
});
checkAction.text = "Check Tile Hopper Map";
checkAction.shortcut = "Ctrl+Shift+F6";

tiled.extendMenu("Map", [
    { separator: true },
    { action: "TileHopperCheck" }
]);
