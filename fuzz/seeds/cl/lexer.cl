GOTO/1,	2 , 3 $
  ,4,5,6 $$ c $
$$ moreGOTO/1.2.3
﻿GOTO/1e400,nan,inf,--1
