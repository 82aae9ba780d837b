<?xml version="1.0" encoding="UTF-8"?>
<tileset version="1.8" tiledversion="1.8.2" name="tiles" tilewidth="16" tileheight="16" tilecount="80" columns="8">
 <image source="tiles.png" width="128" height="160"/>
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
 <tile id="22" type="OneWay"/>
 <tile id="23" type="OneWay"/>
 <tile id="24" type="OneWay"/>
 <tile id="32" type="Solid"/>
 <tile id="33" type="Solid"/>
 <tile id="34" type="Solid"/>
 <tile id="35" type="Solid"/>
 <tile id="36" type="Solid"/>
 <tile id="37" type="Solid"/>
 <tile id="38" type="Solid"/>
 <tile id="39" type="Solid"/>
 <tile id="40" type="Solid"/>
 <tile id="41" type="Solid"/>
 <tile id="42" type="Solid"/>
 <tile id="43" type="Solid"/>
 <tile id="44" type="Solid"/>
 <tile id="45" type="Solid"/>
 <tile id="46" type="Solid"/>
 <tile id="47" type="Solid"/>
 <tile id="48" type="Solid"/>
 <tile id="49" type="Solid"/>
 <tile id="50" type="Solid"/>
 <tile id="51" type="Solid"/>
 <tile id="52" type="Solid"/>
 <tile id="53" type="Solid"/>
 <tile id="54" type="Solid"/>
 <tile id="55" type="Solid"/>
 <tile id="56" type="Solid"/>
 <tile id="57" type="Solid"/>
 <tile id="58" type="Solid"/>
 <tile id="59" type="Solid"/>
 <tile id="60" type="Solid"/>
 <tile id="61" type="Solid"/>
 <tile id="62" type="Solid"/>
 <tile id="63" type="Solid"/>
 <tile id="64" type="Solid"/>
 <tile id="65" type="Solid"/>
 <tile id="66" type="Solid"/>
 <tile id="67" type="Solid"/>
 <tile id="68" type="Solid"/>
 <tile id="69" type="Solid"/>
 <tile id="70" type="Solid"/>
 <tile id="71" type="Solid"/>
 <tile id="72" type="Solid"/>
 <tile id="73" type="Solid"/>
 <tile id="74" type="Solid"/>
 <tile id="75" type="Solid"/>
 <tile id="76" type="Solid"/>
 <tile id="77" type="Solid"/>
 <wangsets>
  <wangset name="Ground" type="mixed" tile="62">
   <wangcolor name="Ground" color="#8c6d46" tile="62" probability="1"/>
   <wangtile tileid="32" wangid="1,0,0,0,0,0,0,0"/>
   <wangtile tileid="33" wangid="0,0,1,0,0,0,0,0"/>
   <wangtile tileid="34" wangid="1,0,1,0,0,0,0,0"/>
   <wangtile tileid="35" wangid="1,1,1,0,0,0,0,0"/>
   <wangtile tileid="36" wangid="0,0,0,0,1,0,0,0"/>
   <wangtile tileid="37" wangid="1,0,0,0,1,0,0,0"/>
   <wangtile tileid="38" wangid="0,0,1,0,1,0,0,0"/>
   <wangtile tileid="39" wangid="1,0,1,0,1,0,0,0"/>
   <wangtile tileid="40" wangid="1,1,1,0,1,0,0,0"/>
   <wangtile tileid="41" wangid="0,0,1,1,1,0,0,0"/>
   <wangtile tileid="42" wangid="1,0,1,1,1,0,0,0"/>
   <wangtile tileid="43" wangid="1,1,1,1,1,0,0,0"/>
   <wangtile tileid="44" wangid="0,0,0,0,0,0,1,0"/>
   <wangtile tileid="45" wangid="1,0,0,0,0,0,1,0"/>
   <wangtile tileid="46" wangid="0,0,1,0,0,0,1,0"/>
   <wangtile tileid="47" wangid="1,0,1,0,0,0,1,0"/>
   <wangtile tileid="48" wangid="1,1,1,0,0,0,1,0"/>
   <wangtile tileid="49" wangid="0,0,0,0,1,0,1,0"/>
   <wangtile tileid="50" wangid="1,0,0,0,1,0,1,0"/>
   <wangtile tileid="51" wangid="0,0,1,0,1,0,1,0"/>
   <wangtile tileid="52" wangid="1,0,1,0,1,0,1,0"/>
   <wangtile tileid="53" wangid="1,1,1,0,1,0,1,0"/>
   <wangtile tileid="54" wangid="0,0,1,1,1,0,1,0"/>
   <wangtile tileid="55" wangid="1,0,1,1,1,0,1,0"/>
   <wangtile tileid="56" wangid="1,1,1,1,1,0,1,0"/>
   <wangtile tileid="57" wangid="0,0,0,0,1,1,1,0"/>
   <wangtile tileid="58" wangid="1,0,0,0,1,1,1,0"/>
   <wangtile tileid="59" wangid="0,0,1,0,1,1,1,0"/>
   <wangtile tileid="60" wangid="1,0,1,0,1,1,1,0"/>
   <wangtile tileid="61" wangid="1,1,1,0,1,1,1,0"/>
   <wangtile tileid="62" wangid="0,0,1,1,1,1,1,0"/>
   <wangtile tileid="63" wangid="1,0,1,1,1,1,1,0"/>
   <wangtile tileid="64" wangid="1,1,1,1,1,1,1,0"/>
   <wangtile tileid="65" wangid="1,0,0,0,0,0,1,1"/>
   <wangtile tileid="66" wangid="1,0,1,0,0,0,1,1"/>
   <wangtile tileid="67" wangid="1,1,1,0,0,0,1,1"/>
   <wangtile tileid="68" wangid="1,0,0,0,1,0,1,1"/>
   <wangtile tileid="69" wangid="1,0,1,0,1,0,1,1"/>
   <wangtile tileid="70" wangid="1,1,1,0,1,0,1,1"/>
   <wangtile tileid="71" wangid="1,0,1,1,1,0,1,1"/>
   <wangtile tileid="72" wangid="1,1,1,1,1,0,1,1"/>
   <wangtile tileid="73" wangid="1,0,0,0,1,1,1,1"/>
   <wangtile tileid="74" wangid="1,0,1,0,1,1,1,1"/>
   <wangtile tileid="75" wangid="1,1,1,0,1,1,1,1"/>
   <wangtile tileid="76" wangid="1,0,1,1,1,1,1,1"/>
   <wangtile tileid="77" wangid="1,1,1,1,1,1,1,1"/>
  </wangset>
  <wangset name="Planks" type="edge" tile="5">
   <wangcolor name="Planks" color="#c8a165" tile="5" probability="1"/>
   <wangtile tileid="5" wangid="0,0,1,0,0,0,1,0"/>
   <wangtile tileid="22" wangid="0,0,1,0,0,0,0,0"/>
   <wangtile tileid="23" wangid="0,0,0,0,0,0,1,0"/>
  </wangset>
 </wangsets>
</tileset>
