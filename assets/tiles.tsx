<?xml version="1.0" encoding="UTF-8"?>
<tileset version="1.8" tiledversion="1.8.2" name="tiles" tilewidth="16" tileheight="16" tilecount="32" columns="8">
 <image source="tiles.png" width="128" height="64"/>
 <tile id="0" type="Solid"/>
 <tile id="1" type="Solid"/>
 <tile id="2" type="Solid"/>
 <tile id="3" type="Solid"/>
 <tile id="4" type="Solid"/>
 <tile id="5" type="OneWay"/>
 <tile id="6" type="Hazard">
  <objectgroup draworder="index" id="2">
   <object id="1" x="1" y="8" width="14" height="8"/>
  </objectgroup>
 </tile>
 <tile id="7" type="Solid"/>
 <tile id="14" type="Solid"/>
 <tile id="15" type="Solid"/>
</tileset>
