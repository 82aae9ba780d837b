<?xml version="1.0" encoding="UTF-8"?>
<tileset version="1.8" tiledversion="1.8.2" name="terrain" tilewidth="16" tileheight="16" tilecount="56" columns="8">
 <image source="terrain.png" width="128" height="112"/>
 <tile id="0" type="Solid"/>
 <tile id="1" type="Solid"/>
 <tile id="2" type="Solid"/>
 <tile id="3" type="Solid"/>
 <tile id="4" type="Solid"/>
 <tile id="5" type="Solid"/>
 <tile id="6" type="Solid"/>
 <tile id="7" type="Solid"/>
 <tile id="8" type="Solid"/>
 <tile id="9" type="Solid"/>
 <tile id="10" type="Solid"/>
 <tile id="11" type="Solid"/>
 <tile id="12" type="Solid"/>
 <tile id="13" type="Solid"/>
 <tile id="14" type="Solid"/>
 <tile id="15" type="Solid"/>
 <tile id="16" type="Solid"/>
 <tile id="17" type="Solid"/>
 <tile id="18" type="Solid"/>
 <tile id="19" type="Solid"/>
 <tile id="20" type="Solid"/>
 <tile id="21" type="Solid"/>
 <tile id="22" type="Solid"/>
 <tile id="23" type="Solid"/>
 <tile id="24" type="Solid"/>
 <tile id="25" type="Solid"/>
 <tile id="26" type="Solid"/>
 <tile id="27" type="Solid"/>
 <tile id="28" type="Solid"/>
 <tile id="29" type="Solid"/>
 <tile id="30" type="Solid"/>
 <tile id="31" type="Solid"/>
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
 <tile id="48" type="OneWay"/>
 <tile id="49" type="OneWay"/>
 <tile id="50" type="OneWay"/>
 <tile id="51" type="OneWay"/>
 <wangsets>
  <wangset name="Ground" type="mixed" tile="31">
   <wangcolor name="Ground" color="#8c6d46" tile="31" probability="1"/>
   <wangtile tileid="1" wangid="1,0,0,0,0,0,0,0"/>
   <wangtile tileid="2" wangid="0,0,1,0,0,0,0,0"/>
   <wangtile tileid="3" wangid="1,0,1,0,0,0,0,0"/>
   <wangtile tileid="4" wangid="1,1,1,0,0,0,0,0"/>
   <wangtile tileid="5" wangid="0,0,0,0,1,0,0,0"/>
   <wangtile tileid="6" wangid="1,0,0,0,1,0,0,0"/>
   <wangtile tileid="7" wangid="0,0,1,0,1,0,0,0"/>
   <wangtile tileid="8" wangid="1,0,1,0,1,0,0,0"/>
   <wangtile tileid="9" wangid="1,1,1,0,1,0,0,0"/>
   <wangtile tileid="10" wangid="0,0,1,1,1,0,0,0"/>
   <wangtile tileid="11" wangid="1,0,1,1,1,0,0,0"/>
   <wangtile tileid="12" wangid="1,1,1,1,1,0,0,0"/>
   <wangtile tileid="13" wangid="0,0,0,0,0,0,1,0"/>
   <wangtile tileid="14" wangid="1,0,0,0,0,0,1,0"/>
   <wangtile tileid="15" wangid="0,0,1,0,0,0,1,0"/>
   <wangtile tileid="16" wangid="1,0,1,0,0,0,1,0"/>
   <wangtile tileid="17" wangid="1,1,1,0,0,0,1,0"/>
   <wangtile tileid="18" wangid="0,0,0,0,1,0,1,0"/>
   <wangtile tileid="19" wangid="1,0,0,0,1,0,1,0"/>
   <wangtile tileid="20" wangid="0,0,1,0,1,0,1,0"/>
   <wangtile tileid="21" wangid="1,0,1,0,1,0,1,0"/>
   <wangtile tileid="22" wangid="1,1,1,0,1,0,1,0"/>
   <wangtile tileid="23" wangid="0,0,1,1,1,0,1,0"/>
   <wangtile tileid="24" wangid="1,0,1,1,1,0,1,0"/>
   <wangtile tileid="25" wangid="1,1,1,1,1,0,1,0"/>
   <wangtile tileid="26" wangid="0,0,0,0,1,1,1,0"/>
   <wangtile tileid="27" wangid="1,0,0,0,1,1,1,0"/>
   <wangtile tileid="28" wangid="0,0,1,0,1,1,1,0"/>
   <wangtile tileid="29" wangid="1,0,1,0,1,1,1,0"/>
   <wangtile tileid="30" wangid="1,1,1,0,1,1,1,0"/>
   <wangtile tileid="31" wangid="0,0,1,1,1,1,1,0"/>
   <wangtile tileid="32" wangid="1,0,1,1,1,1,1,0"/>
   <wangtile tileid="33" wangid="1,1,1,1,1,1,1,0"/>
   <wangtile tileid="34" wangid="1,0,0,0,0,0,1,1"/>
   <wangtile tileid="35" wangid="1,0,1,0,0,0,1,1"/>
   <wangtile tileid="36" wangid="1,1,1,0,0,0,1,1"/>
   <wangtile tileid="37" wangid="1,0,0,0,1,0,1,1"/>
   <wangtile tileid="38" wangid="1,0,1,0,1,0,1,1"/>
   <wangtile tileid="39" wangid="1,1,1,0,1,0,1,1"/>
   <wangtile tileid="40" wangid="1,0,1,1,1,0,1,1"/>
   <wangtile tileid="41" wangid="1,1,1,1,1,0,1,1"/>
   <wangtile tileid="42" wangid="1,0,0,0,1,1,1,1"/>
   <wangtile tileid="43" wangid="1,0,1,0,1,1,1,1"/>
   <wangtile tileid="44" wangid="1,1,1,0,1,1,1,1"/>
   <wangtile tileid="45" wangid="1,0,1,1,1,1,1,1"/>
   <wangtile tileid="46" wangid="1,1,1,1,1,1,1,1"/>
  </wangset>
  <wangset name="Planks" type="edge" tile="49">
   <wangcolor name="Planks" color="#c8a165" tile="49" probability="1"/>
   <wangtile tileid="49" wangid="0,0,1,0,0,0,1,0"/>
   <wangtile tileid="48" wangid="0,0,1,0,0,0,0,0"/>
   <wangtile tileid="50" wangid="0,0,0,0,0,0,1,0"/>
  </wangset>
 </wangsets>
</tileset>
