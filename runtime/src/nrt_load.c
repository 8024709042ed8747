/* nrt_load.c - validates a champion blob byte by byte and lays the network out in the caller's memory. */
#include <string.h>

#include "nrt.h"

static uint16_t nrt_rd16(const uint8_t *p)
{
    return (uint16_t)(p[0] | (p[1] << 8));
}

static uint32_t nrt_rd32(const uint8_t *p)
{
    return (uint32_t)p[0] | ((uint32_t)p[1] << 8) | ((uint32_t)p[2] << 16) | ((uint32_t)p[3] << 24);
}

#ifndef __OPTIMIZE_SIZE__
/* nrt_crc32_table[0][n] = the CRC register after the 8 bitwise steps from n;
 * [k][n] = ([k-1][n] >> 8) ^ [0][[k-1][n] & 0xFF], the register after k more
 * zero bytes, so four bytes go in one step (tests/runtime/test_loader.c
 * compares with the bitwise CRC on random data of every length and start). */
static const uint32_t nrt_crc32_table[4][256] = {
    {
        0x00000000u, 0x77073096u, 0xEE0E612Cu, 0x990951BAu, 0x076DC419u, 0x706AF48Fu,
        0xE963A535u, 0x9E6495A3u, 0x0EDB8832u, 0x79DCB8A4u, 0xE0D5E91Eu, 0x97D2D988u,
        0x09B64C2Bu, 0x7EB17CBDu, 0xE7B82D07u, 0x90BF1D91u, 0x1DB71064u, 0x6AB020F2u,
        0xF3B97148u, 0x84BE41DEu, 0x1ADAD47Du, 0x6DDDE4EBu, 0xF4D4B551u, 0x83D385C7u,
        0x136C9856u, 0x646BA8C0u, 0xFD62F97Au, 0x8A65C9ECu, 0x14015C4Fu, 0x63066CD9u,
        0xFA0F3D63u, 0x8D080DF5u, 0x3B6E20C8u, 0x4C69105Eu, 0xD56041E4u, 0xA2677172u,
        0x3C03E4D1u, 0x4B04D447u, 0xD20D85FDu, 0xA50AB56Bu, 0x35B5A8FAu, 0x42B2986Cu,
        0xDBBBC9D6u, 0xACBCF940u, 0x32D86CE3u, 0x45DF5C75u, 0xDCD60DCFu, 0xABD13D59u,
        0x26D930ACu, 0x51DE003Au, 0xC8D75180u, 0xBFD06116u, 0x21B4F4B5u, 0x56B3C423u,
        0xCFBA9599u, 0xB8BDA50Fu, 0x2802B89Eu, 0x5F058808u, 0xC60CD9B2u, 0xB10BE924u,
        0x2F6F7C87u, 0x58684C11u, 0xC1611DABu, 0xB6662D3Du, 0x76DC4190u, 0x01DB7106u,
        0x98D220BCu, 0xEFD5102Au, 0x71B18589u, 0x06B6B51Fu, 0x9FBFE4A5u, 0xE8B8D433u,
        0x7807C9A2u, 0x0F00F934u, 0x9609A88Eu, 0xE10E9818u, 0x7F6A0DBBu, 0x086D3D2Du,
        0x91646C97u, 0xE6635C01u, 0x6B6B51F4u, 0x1C6C6162u, 0x856530D8u, 0xF262004Eu,
        0x6C0695EDu, 0x1B01A57Bu, 0x8208F4C1u, 0xF50FC457u, 0x65B0D9C6u, 0x12B7E950u,
        0x8BBEB8EAu, 0xFCB9887Cu, 0x62DD1DDFu, 0x15DA2D49u, 0x8CD37CF3u, 0xFBD44C65u,
        0x4DB26158u, 0x3AB551CEu, 0xA3BC0074u, 0xD4BB30E2u, 0x4ADFA541u, 0x3DD895D7u,
        0xA4D1C46Du, 0xD3D6F4FBu, 0x4369E96Au, 0x346ED9FCu, 0xAD678846u, 0xDA60B8D0u,
        0x44042D73u, 0x33031DE5u, 0xAA0A4C5Fu, 0xDD0D7CC9u, 0x5005713Cu, 0x270241AAu,
        0xBE0B1010u, 0xC90C2086u, 0x5768B525u, 0x206F85B3u, 0xB966D409u, 0xCE61E49Fu,
        0x5EDEF90Eu, 0x29D9C998u, 0xB0D09822u, 0xC7D7A8B4u, 0x59B33D17u, 0x2EB40D81u,
        0xB7BD5C3Bu, 0xC0BA6CADu, 0xEDB88320u, 0x9ABFB3B6u, 0x03B6E20Cu, 0x74B1D29Au,
        0xEAD54739u, 0x9DD277AFu, 0x04DB2615u, 0x73DC1683u, 0xE3630B12u, 0x94643B84u,
        0x0D6D6A3Eu, 0x7A6A5AA8u, 0xE40ECF0Bu, 0x9309FF9Du, 0x0A00AE27u, 0x7D079EB1u,
        0xF00F9344u, 0x8708A3D2u, 0x1E01F268u, 0x6906C2FEu, 0xF762575Du, 0x806567CBu,
        0x196C3671u, 0x6E6B06E7u, 0xFED41B76u, 0x89D32BE0u, 0x10DA7A5Au, 0x67DD4ACCu,
        0xF9B9DF6Fu, 0x8EBEEFF9u, 0x17B7BE43u, 0x60B08ED5u, 0xD6D6A3E8u, 0xA1D1937Eu,
        0x38D8C2C4u, 0x4FDFF252u, 0xD1BB67F1u, 0xA6BC5767u, 0x3FB506DDu, 0x48B2364Bu,
        0xD80D2BDAu, 0xAF0A1B4Cu, 0x36034AF6u, 0x41047A60u, 0xDF60EFC3u, 0xA867DF55u,
        0x316E8EEFu, 0x4669BE79u, 0xCB61B38Cu, 0xBC66831Au, 0x256FD2A0u, 0x5268E236u,
        0xCC0C7795u, 0xBB0B4703u, 0x220216B9u, 0x5505262Fu, 0xC5BA3BBEu, 0xB2BD0B28u,
        0x2BB45A92u, 0x5CB36A04u, 0xC2D7FFA7u, 0xB5D0CF31u, 0x2CD99E8Bu, 0x5BDEAE1Du,
        0x9B64C2B0u, 0xEC63F226u, 0x756AA39Cu, 0x026D930Au, 0x9C0906A9u, 0xEB0E363Fu,
        0x72076785u, 0x05005713u, 0x95BF4A82u, 0xE2B87A14u, 0x7BB12BAEu, 0x0CB61B38u,
        0x92D28E9Bu, 0xE5D5BE0Du, 0x7CDCEFB7u, 0x0BDBDF21u, 0x86D3D2D4u, 0xF1D4E242u,
        0x68DDB3F8u, 0x1FDA836Eu, 0x81BE16CDu, 0xF6B9265Bu, 0x6FB077E1u, 0x18B74777u,
        0x88085AE6u, 0xFF0F6A70u, 0x66063BCAu, 0x11010B5Cu, 0x8F659EFFu, 0xF862AE69u,
        0x616BFFD3u, 0x166CCF45u, 0xA00AE278u, 0xD70DD2EEu, 0x4E048354u, 0x3903B3C2u,
        0xA7672661u, 0xD06016F7u, 0x4969474Du, 0x3E6E77DBu, 0xAED16A4Au, 0xD9D65ADCu,
        0x40DF0B66u, 0x37D83BF0u, 0xA9BCAE53u, 0xDEBB9EC5u, 0x47B2CF7Fu, 0x30B5FFE9u,
        0xBDBDF21Cu, 0xCABAC28Au, 0x53B39330u, 0x24B4A3A6u, 0xBAD03605u, 0xCDD70693u,
        0x54DE5729u, 0x23D967BFu, 0xB3667A2Eu, 0xC4614AB8u, 0x5D681B02u, 0x2A6F2B94u,
        0xB40BBE37u, 0xC30C8EA1u, 0x5A05DF1Bu, 0x2D02EF8Du,
    },
    {
        0x00000000u, 0x191B3141u, 0x32366282u, 0x2B2D53C3u, 0x646CC504u, 0x7D77F445u,
        0x565AA786u, 0x4F4196C7u, 0xC8D98A08u, 0xD1C2BB49u, 0xFAEFE88Au, 0xE3F4D9CBu,
        0xACB54F0Cu, 0xB5AE7E4Du, 0x9E832D8Eu, 0x87981CCFu, 0x4AC21251u, 0x53D92310u,
        0x78F470D3u, 0x61EF4192u, 0x2EAED755u, 0x37B5E614u, 0x1C98B5D7u, 0x05838496u,
        0x821B9859u, 0x9B00A918u, 0xB02DFADBu, 0xA936CB9Au, 0xE6775D5Du, 0xFF6C6C1Cu,
        0xD4413FDFu, 0xCD5A0E9Eu, 0x958424A2u, 0x8C9F15E3u, 0xA7B24620u, 0xBEA97761u,
        0xF1E8E1A6u, 0xE8F3D0E7u, 0xC3DE8324u, 0xDAC5B265u, 0x5D5DAEAAu, 0x44469FEBu,
        0x6F6BCC28u, 0x7670FD69u, 0x39316BAEu, 0x202A5AEFu, 0x0B07092Cu, 0x121C386Du,
        0xDF4636F3u, 0xC65D07B2u, 0xED705471u, 0xF46B6530u, 0xBB2AF3F7u, 0xA231C2B6u,
        0x891C9175u, 0x9007A034u, 0x179FBCFBu, 0x0E848DBAu, 0x25A9DE79u, 0x3CB2EF38u,
        0x73F379FFu, 0x6AE848BEu, 0x41C51B7Du, 0x58DE2A3Cu, 0xF0794F05u, 0xE9627E44u,
        0xC24F2D87u, 0xDB541CC6u, 0x94158A01u, 0x8D0EBB40u, 0xA623E883u, 0xBF38D9C2u,
        0x38A0C50Du, 0x21BBF44Cu, 0x0A96A78Fu, 0x138D96CEu, 0x5CCC0009u, 0x45D73148u,
        0x6EFA628Bu, 0x77E153CAu, 0xBABB5D54u, 0xA3A06C15u, 0x888D3FD6u, 0x91960E97u,
        0xDED79850u, 0xC7CCA911u, 0xECE1FAD2u, 0xF5FACB93u, 0x7262D75Cu, 0x6B79E61Du,
        0x4054B5DEu, 0x594F849Fu, 0x160E1258u, 0x0F152319u, 0x243870DAu, 0x3D23419Bu,
        0x65FD6BA7u, 0x7CE65AE6u, 0x57CB0925u, 0x4ED03864u, 0x0191AEA3u, 0x188A9FE2u,
        0x33A7CC21u, 0x2ABCFD60u, 0xAD24E1AFu, 0xB43FD0EEu, 0x9F12832Du, 0x8609B26Cu,
        0xC94824ABu, 0xD05315EAu, 0xFB7E4629u, 0xE2657768u, 0x2F3F79F6u, 0x362448B7u,
        0x1D091B74u, 0x04122A35u, 0x4B53BCF2u, 0x52488DB3u, 0x7965DE70u, 0x607EEF31u,
        0xE7E6F3FEu, 0xFEFDC2BFu, 0xD5D0917Cu, 0xCCCBA03Du, 0x838A36FAu, 0x9A9107BBu,
        0xB1BC5478u, 0xA8A76539u, 0x3B83984Bu, 0x2298A90Au, 0x09B5FAC9u, 0x10AECB88u,
        0x5FEF5D4Fu, 0x46F46C0Eu, 0x6DD93FCDu, 0x74C20E8Cu, 0xF35A1243u, 0xEA412302u,
        0xC16C70C1u, 0xD8774180u, 0x9736D747u, 0x8E2DE606u, 0xA500B5C5u, 0xBC1B8484u,
        0x71418A1Au, 0x685ABB5Bu, 0x4377E898u, 0x5A6CD9D9u, 0x152D4F1Eu, 0x0C367E5Fu,
        0x271B2D9Cu, 0x3E001CDDu, 0xB9980012u, 0xA0833153u, 0x8BAE6290u, 0x92B553D1u,
        0xDDF4C516u, 0xC4EFF457u, 0xEFC2A794u, 0xF6D996D5u, 0xAE07BCE9u, 0xB71C8DA8u,
        0x9C31DE6Bu, 0x852AEF2Au, 0xCA6B79EDu, 0xD37048ACu, 0xF85D1B6Fu, 0xE1462A2Eu,
        0x66DE36E1u, 0x7FC507A0u, 0x54E85463u, 0x4DF36522u, 0x02B2F3E5u, 0x1BA9C2A4u,
        0x30849167u, 0x299FA026u, 0xE4C5AEB8u, 0xFDDE9FF9u, 0xD6F3CC3Au, 0xCFE8FD7Bu,
        0x80A96BBCu, 0x99B25AFDu, 0xB29F093Eu, 0xAB84387Fu, 0x2C1C24B0u, 0x350715F1u,
        0x1E2A4632u, 0x07317773u, 0x4870E1B4u, 0x516BD0F5u, 0x7A468336u, 0x635DB277u,
        0xCBFAD74Eu, 0xD2E1E60Fu, 0xF9CCB5CCu, 0xE0D7848Du, 0xAF96124Au, 0xB68D230Bu,
        0x9DA070C8u, 0x84BB4189u, 0x03235D46u, 0x1A386C07u, 0x31153FC4u, 0x280E0E85u,
        0x674F9842u, 0x7E54A903u, 0x5579FAC0u, 0x4C62CB81u, 0x8138C51Fu, 0x9823F45Eu,
        0xB30EA79Du, 0xAA1596DCu, 0xE554001Bu, 0xFC4F315Au, 0xD7626299u, 0xCE7953D8u,
        0x49E14F17u, 0x50FA7E56u, 0x7BD72D95u, 0x62CC1CD4u, 0x2D8D8A13u, 0x3496BB52u,
        0x1FBBE891u, 0x06A0D9D0u, 0x5E7EF3ECu, 0x4765C2ADu, 0x6C48916Eu, 0x7553A02Fu,
        0x3A1236E8u, 0x230907A9u, 0x0824546Au, 0x113F652Bu, 0x96A779E4u, 0x8FBC48A5u,
        0xA4911B66u, 0xBD8A2A27u, 0xF2CBBCE0u, 0xEBD08DA1u, 0xC0FDDE62u, 0xD9E6EF23u,
        0x14BCE1BDu, 0x0DA7D0FCu, 0x268A833Fu, 0x3F91B27Eu, 0x70D024B9u, 0x69CB15F8u,
        0x42E6463Bu, 0x5BFD777Au, 0xDC656BB5u, 0xC57E5AF4u, 0xEE530937u, 0xF7483876u,
        0xB809AEB1u, 0xA1129FF0u, 0x8A3FCC33u, 0x9324FD72u,
    },
    {
        0x00000000u, 0x01C26A37u, 0x0384D46Eu, 0x0246BE59u, 0x0709A8DCu, 0x06CBC2EBu,
        0x048D7CB2u, 0x054F1685u, 0x0E1351B8u, 0x0FD13B8Fu, 0x0D9785D6u, 0x0C55EFE1u,
        0x091AF964u, 0x08D89353u, 0x0A9E2D0Au, 0x0B5C473Du, 0x1C26A370u, 0x1DE4C947u,
        0x1FA2771Eu, 0x1E601D29u, 0x1B2F0BACu, 0x1AED619Bu, 0x18ABDFC2u, 0x1969B5F5u,
        0x1235F2C8u, 0x13F798FFu, 0x11B126A6u, 0x10734C91u, 0x153C5A14u, 0x14FE3023u,
        0x16B88E7Au, 0x177AE44Du, 0x384D46E0u, 0x398F2CD7u, 0x3BC9928Eu, 0x3A0BF8B9u,
        0x3F44EE3Cu, 0x3E86840Bu, 0x3CC03A52u, 0x3D025065u, 0x365E1758u, 0x379C7D6Fu,
        0x35DAC336u, 0x3418A901u, 0x3157BF84u, 0x3095D5B3u, 0x32D36BEAu, 0x331101DDu,
        0x246BE590u, 0x25A98FA7u, 0x27EF31FEu, 0x262D5BC9u, 0x23624D4Cu, 0x22A0277Bu,
        0x20E69922u, 0x2124F315u, 0x2A78B428u, 0x2BBADE1Fu, 0x29FC6046u, 0x283E0A71u,
        0x2D711CF4u, 0x2CB376C3u, 0x2EF5C89Au, 0x2F37A2ADu, 0x709A8DC0u, 0x7158E7F7u,
        0x731E59AEu, 0x72DC3399u, 0x7793251Cu, 0x76514F2Bu, 0x7417F172u, 0x75D59B45u,
        0x7E89DC78u, 0x7F4BB64Fu, 0x7D0D0816u, 0x7CCF6221u, 0x798074A4u, 0x78421E93u,
        0x7A04A0CAu, 0x7BC6CAFDu, 0x6CBC2EB0u, 0x6D7E4487u, 0x6F38FADEu, 0x6EFA90E9u,
        0x6BB5866Cu, 0x6A77EC5Bu, 0x68315202u, 0x69F33835u, 0x62AF7F08u, 0x636D153Fu,
        0x612BAB66u, 0x60E9C151u, 0x65A6D7D4u, 0x6464BDE3u, 0x662203BAu, 0x67E0698Du,
        0x48D7CB20u, 0x4915A117u, 0x4B531F4Eu, 0x4A917579u, 0x4FDE63FCu, 0x4E1C09CBu,
        0x4C5AB792u, 0x4D98DDA5u, 0x46C49A98u, 0x4706F0AFu, 0x45404EF6u, 0x448224C1u,
        0x41CD3244u, 0x400F5873u, 0x4249E62Au, 0x438B8C1Du, 0x54F16850u, 0x55330267u,
        0x5775BC3Eu, 0x56B7D609u, 0x53F8C08Cu, 0x523AAABBu, 0x507C14E2u, 0x51BE7ED5u,
        0x5AE239E8u, 0x5B2053DFu, 0x5966ED86u, 0x58A487B1u, 0x5DEB9134u, 0x5C29FB03u,
        0x5E6F455Au, 0x5FAD2F6Du, 0xE1351B80u, 0xE0F771B7u, 0xE2B1CFEEu, 0xE373A5D9u,
        0xE63CB35Cu, 0xE7FED96Bu, 0xE5B86732u, 0xE47A0D05u, 0xEF264A38u, 0xEEE4200Fu,
        0xECA29E56u, 0xED60F461u, 0xE82FE2E4u, 0xE9ED88D3u, 0xEBAB368Au, 0xEA695CBDu,
        0xFD13B8F0u, 0xFCD1D2C7u, 0xFE976C9Eu, 0xFF5506A9u, 0xFA1A102Cu, 0xFBD87A1Bu,
        0xF99EC442u, 0xF85CAE75u, 0xF300E948u, 0xF2C2837Fu, 0xF0843D26u, 0xF1465711u,
        0xF4094194u, 0xF5CB2BA3u, 0xF78D95FAu, 0xF64FFFCDu, 0xD9785D60u, 0xD8BA3757u,
        0xDAFC890Eu, 0xDB3EE339u, 0xDE71F5BCu, 0xDFB39F8Bu, 0xDDF521D2u, 0xDC374BE5u,
        0xD76B0CD8u, 0xD6A966EFu, 0xD4EFD8B6u, 0xD52DB281u, 0xD062A404u, 0xD1A0CE33u,
        0xD3E6706Au, 0xD2241A5Du, 0xC55EFE10u, 0xC49C9427u, 0xC6DA2A7Eu, 0xC7184049u,
        0xC25756CCu, 0xC3953CFBu, 0xC1D382A2u, 0xC011E895u, 0xCB4DAFA8u, 0xCA8FC59Fu,
        0xC8C97BC6u, 0xC90B11F1u, 0xCC440774u, 0xCD866D43u, 0xCFC0D31Au, 0xCE02B92Du,
        0x91AF9640u, 0x906DFC77u, 0x922B422Eu, 0x93E92819u, 0x96A63E9Cu, 0x976454ABu,
        0x9522EAF2u, 0x94E080C5u, 0x9FBCC7F8u, 0x9E7EADCFu, 0x9C381396u, 0x9DFA79A1u,
        0x98B56F24u, 0x99770513u, 0x9B31BB4Au, 0x9AF3D17Du, 0x8D893530u, 0x8C4B5F07u,
        0x8E0DE15Eu, 0x8FCF8B69u, 0x8A809DECu, 0x8B42F7DBu, 0x89044982u, 0x88C623B5u,
        0x839A6488u, 0x82580EBFu, 0x801EB0E6u, 0x81DCDAD1u, 0x8493CC54u, 0x8551A663u,
        0x8717183Au, 0x86D5720Du, 0xA9E2D0A0u, 0xA820BA97u, 0xAA6604CEu, 0xABA46EF9u,
        0xAEEB787Cu, 0xAF29124Bu, 0xAD6FAC12u, 0xACADC625u, 0xA7F18118u, 0xA633EB2Fu,
        0xA4755576u, 0xA5B73F41u, 0xA0F829C4u, 0xA13A43F3u, 0xA37CFDAAu, 0xA2BE979Du,
        0xB5C473D0u, 0xB40619E7u, 0xB640A7BEu, 0xB782CD89u, 0xB2CDDB0Cu, 0xB30FB13Bu,
        0xB1490F62u, 0xB08B6555u, 0xBBD72268u, 0xBA15485Fu, 0xB853F606u, 0xB9919C31u,
        0xBCDE8AB4u, 0xBD1CE083u, 0xBF5A5EDAu, 0xBE9834EDu,
    },
    {
        0x00000000u, 0xB8BC6765u, 0xAA09C88Bu, 0x12B5AFEEu, 0x8F629757u, 0x37DEF032u,
        0x256B5FDCu, 0x9DD738B9u, 0xC5B428EFu, 0x7D084F8Au, 0x6FBDE064u, 0xD7018701u,
        0x4AD6BFB8u, 0xF26AD8DDu, 0xE0DF7733u, 0x58631056u, 0x5019579Fu, 0xE8A530FAu,
        0xFA109F14u, 0x42ACF871u, 0xDF7BC0C8u, 0x67C7A7ADu, 0x75720843u, 0xCDCE6F26u,
        0x95AD7F70u, 0x2D111815u, 0x3FA4B7FBu, 0x8718D09Eu, 0x1ACFE827u, 0xA2738F42u,
        0xB0C620ACu, 0x087A47C9u, 0xA032AF3Eu, 0x188EC85Bu, 0x0A3B67B5u, 0xB28700D0u,
        0x2F503869u, 0x97EC5F0Cu, 0x8559F0E2u, 0x3DE59787u, 0x658687D1u, 0xDD3AE0B4u,
        0xCF8F4F5Au, 0x7733283Fu, 0xEAE41086u, 0x525877E3u, 0x40EDD80Du, 0xF851BF68u,
        0xF02BF8A1u, 0x48979FC4u, 0x5A22302Au, 0xE29E574Fu, 0x7F496FF6u, 0xC7F50893u,
        0xD540A77Du, 0x6DFCC018u, 0x359FD04Eu, 0x8D23B72Bu, 0x9F9618C5u, 0x272A7FA0u,
        0xBAFD4719u, 0x0241207Cu, 0x10F48F92u, 0xA848E8F7u, 0x9B14583Du, 0x23A83F58u,
        0x311D90B6u, 0x89A1F7D3u, 0x1476CF6Au, 0xACCAA80Fu, 0xBE7F07E1u, 0x06C36084u,
        0x5EA070D2u, 0xE61C17B7u, 0xF4A9B859u, 0x4C15DF3Cu, 0xD1C2E785u, 0x697E80E0u,
        0x7BCB2F0Eu, 0xC377486Bu, 0xCB0D0FA2u, 0x73B168C7u, 0x6104C729u, 0xD9B8A04Cu,
        0x446F98F5u, 0xFCD3FF90u, 0xEE66507Eu, 0x56DA371Bu, 0x0EB9274Du, 0xB6054028u,
        0xA4B0EFC6u, 0x1C0C88A3u, 0x81DBB01Au, 0x3967D77Fu, 0x2BD27891u, 0x936E1FF4u,
        0x3B26F703u, 0x839A9066u, 0x912F3F88u, 0x299358EDu, 0xB4446054u, 0x0CF80731u,
        0x1E4DA8DFu, 0xA6F1CFBAu, 0xFE92DFECu, 0x462EB889u, 0x549B1767u, 0xEC277002u,
        0x71F048BBu, 0xC94C2FDEu, 0xDBF98030u, 0x6345E755u, 0x6B3FA09Cu, 0xD383C7F9u,
        0xC1366817u, 0x798A0F72u, 0xE45D37CBu, 0x5CE150AEu, 0x4E54FF40u, 0xF6E89825u,
        0xAE8B8873u, 0x1637EF16u, 0x048240F8u, 0xBC3E279Du, 0x21E91F24u, 0x99557841u,
        0x8BE0D7AFu, 0x335CB0CAu, 0xED59B63Bu, 0x55E5D15Eu, 0x47507EB0u, 0xFFEC19D5u,
        0x623B216Cu, 0xDA874609u, 0xC832E9E7u, 0x708E8E82u, 0x28ED9ED4u, 0x9051F9B1u,
        0x82E4565Fu, 0x3A58313Au, 0xA78F0983u, 0x1F336EE6u, 0x0D86C108u, 0xB53AA66Du,
        0xBD40E1A4u, 0x05FC86C1u, 0x1749292Fu, 0xAFF54E4Au, 0x322276F3u, 0x8A9E1196u,
        0x982BBE78u, 0x2097D91Du, 0x78F4C94Bu, 0xC048AE2Eu, 0xD2FD01C0u, 0x6A4166A5u,
        0xF7965E1Cu, 0x4F2A3979u, 0x5D9F9697u, 0xE523F1F2u, 0x4D6B1905u, 0xF5D77E60u,
        0xE762D18Eu, 0x5FDEB6EBu, 0xC2098E52u, 0x7AB5E937u, 0x680046D9u, 0xD0BC21BCu,
        0x88DF31EAu, 0x3063568Fu, 0x22D6F961u, 0x9A6A9E04u, 0x07BDA6BDu, 0xBF01C1D8u,
        0xADB46E36u, 0x15080953u, 0x1D724E9Au, 0xA5CE29FFu, 0xB77B8611u, 0x0FC7E174u,
        0x9210D9CDu, 0x2AACBEA8u, 0x38191146u, 0x80A57623u, 0xD8C66675u, 0x607A0110u,
        0x72CFAEFEu, 0xCA73C99Bu, 0x57A4F122u, 0xEF189647u, 0xFDAD39A9u, 0x45115ECCu,
        0x764DEE06u, 0xCEF18963u, 0xDC44268Du, 0x64F841E8u, 0xF92F7951u, 0x41931E34u,
        0x5326B1DAu, 0xEB9AD6BFu, 0xB3F9C6E9u, 0x0B45A18Cu, 0x19F00E62u, 0xA14C6907u,
        0x3C9B51BEu, 0x842736DBu, 0x96929935u, 0x2E2EFE50u, 0x2654B999u, 0x9EE8DEFCu,
        0x8C5D7112u, 0x34E11677u, 0xA9362ECEu, 0x118A49ABu, 0x033FE645u, 0xBB838120u,
        0xE3E09176u, 0x5B5CF613u, 0x49E959FDu, 0xF1553E98u, 0x6C820621u, 0xD43E6144u,
        0xC68BCEAAu, 0x7E37A9CFu, 0xD67F4138u, 0x6EC3265Du, 0x7C7689B3u, 0xC4CAEED6u,
        0x591DD66Fu, 0xE1A1B10Au, 0xF3141EE4u, 0x4BA87981u, 0x13CB69D7u, 0xAB770EB2u,
        0xB9C2A15Cu, 0x017EC639u, 0x9CA9FE80u, 0x241599E5u, 0x36A0360Bu, 0x8E1C516Eu,
        0x866616A7u, 0x3EDA71C2u, 0x2C6FDE2Cu, 0x94D3B949u, 0x090481F0u, 0xB1B8E695u,
        0xA30D497Bu, 0x1BB12E1Eu, 0x43D23E48u, 0xFB6E592Du, 0xE9DBF6C3u, 0x516791A6u,
        0xCCB0A91Fu, 0x740CCE7Au, 0x66B96194u, 0xDE0506F1u,
    },
};
#endif

uint32_t nrt_crc32(uint32_t crc, const void *data, size_t len)
{
    const uint8_t *p = (const uint8_t *)data;
    size_t i;
    crc = ~crc;
#ifdef __OPTIMIZE_SIZE__
    /* Bitwise, no table at -Os (the firmware): it runs once per load and a
     * table would cost 1 KiB of flash. */
    for (i = 0; i < len; i++) {
        int b;
        crc ^= p[i];
        for (b = 0; b < 8; b++)
            crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
    }
#else
    /* Four bytes a step on hosts (slicing by four), where checkpoints of
     * megabytes are checksummed every generation and every evaluated network
     * is a blob written and loaded (the bitwise loop was 3-5 % of a
     * paper-scale generation; a byte a lookup, 9 % of neat_bench xor) */
    for (i = 0; i + 4 <= len; i += 4) {
        crc ^= (uint32_t)p[i] | ((uint32_t)p[i + 1] << 8) | ((uint32_t)p[i + 2] << 16) | ((uint32_t)p[i + 3] << 24);
        crc = nrt_crc32_table[3][crc & 0xFFu] ^ nrt_crc32_table[2][(crc >> 8) & 0xFFu] ^
              nrt_crc32_table[1][(crc >> 16) & 0xFFu] ^ nrt_crc32_table[0][crc >> 24];
    }
    for (; i < len; i++)
        crc = (crc >> 8) ^ nrt_crc32_table[0][(crc ^ p[i]) & 0xFFu];
#endif
    return ~crc;
}

/* Memory nrt_load lays out, all 16-bit arrays: weights and sources of the
 * connections, ends of each node's run, two activation arrays; +1 to align
 * a buffer of any address. A propagate network adds its evaluation order,
 * a byte a non-input node, after them (so a sync network's layout, and its
 * size, are what they were before the mode existed). */
static size_t nrt_mem_for(uint32_t nodes, uint32_t non_inputs, uint32_t conns, uint32_t step)
{
    return 4u * conns + 2u * non_inputs + 4u * nodes + 1u + (step == NRT_STEP_PROPAGATE ? non_inputs : 0u);
}

int nrt_inspect(const uint8_t *blob, size_t len, size_t *blob_size, size_t *mem_required)
{
    uint32_t n_in, n_out, n_hid, n_conns, nodes, total, version, step;
    if (blob == NULL)
        return NRT_E_ARG;
    if (len < NRT_HEADER_SIZE)
        return NRT_E_TRUNCATED;
    if (blob[0] != NRT_MAGIC0 || blob[1] != NRT_MAGIC1 || blob[2] != NRT_MAGIC2 || blob[3] != NRT_MAGIC3)
        return NRT_E_MAGIC;
    version = nrt_rd16(blob + NRT_OFF_VERSION);
#ifdef NRT_NO_PROPAGATE
    /* a sync-only runtime: a propagate blob is a version it does not know */
    if (version != NRT_FORMAT_VERSION)
        return NRT_E_VERSION;
#else
    if (version != NRT_FORMAT_VERSION && version != NRT_FORMAT_VERSION_PROPAGATE)
        return NRT_E_VERSION;
#endif
    if (nrt_rd16(blob + NRT_OFF_HEADER_SIZE) != NRT_HEADER_SIZE || blob[NRT_OFF_WEIGHT_BITS] != NRT_WEIGHT_FRAC_BITS ||
        blob[NRT_OFF_ACTIVATION] != NRT_ACT_SIGMOID49)
        return NRT_E_HEADER;
    /* Version 1 is sync with the step byte zero; version 2 must name
     * propagate: one encoding per network, and no version-2 blob a
     * version-1 loader could mistake for sync. */
    step = blob[NRT_OFF_STEP];
    if (step != (version == NRT_FORMAT_VERSION ? NRT_STEP_SYNC : NRT_STEP_PROPAGATE))
        return NRT_E_HEADER;
    {
        int i;
        for (i = NRT_OFF_STEP + 1; i < NRT_OFF_CRC; i++)
            if (blob[i] != 0)
                return NRT_E_HEADER;
    }
    n_in = nrt_rd16(blob + NRT_OFF_INPUTS);
    n_out = nrt_rd16(blob + NRT_OFF_OUTPUTS);
    n_hid = nrt_rd16(blob + NRT_OFF_HIDDEN);
    n_conns = nrt_rd16(blob + NRT_OFF_CONNS);
    nodes = n_in + n_out + n_hid;
    if (n_in < 1 || n_out < 1 || nodes > NRT_MAX_NODES)
        return NRT_E_COUNTS;
    total = nrt_rd32(blob + NRT_OFF_TOTAL_SIZE);
    if (total != NRT_HEADER_SIZE + NRT_CONN_SIZE * n_conns)
        return NRT_E_COUNTS;
    if (blob_size != NULL)
        *blob_size = total;
    if (mem_required != NULL)
        *mem_required = nrt_mem_for(nodes, n_out + n_hid, n_conns, step);
    return NRT_OK;
}

int nrt_mem_required(const uint8_t *blob, size_t len, size_t *mem_required)
{
    return nrt_inspect(blob, len, NULL, mem_required);
}

#ifndef NRT_NO_PROPAGATE
/* A propagate network's evaluation order into net->order. Computed here
 * rather than stored in the blob: the order is a function of the
 * connections, so a blob cannot carry one that disagrees with them, a
 * version-2 blob is a version-1 blob with the step byte set, and there is
 * nothing more to check. The rule (docs/runtime.md, "Semantics"): place,
 * one at a time, the lowest-index unplaced node all of whose sources other
 * than itself are inputs or placed; when none is (only cycles remain), the
 * lowest-index unplaced node. At most N rounds of N + C checks (202
 * connections and 27 non-input nodes: under 6,200). src and end are laid
 * out (target order); act[0], which nrt_reset zeroes next, holds the
 * placed flags meanwhile. */
static void nrt_order(nrt_net *net)
{
    uint32_t n_in = net->n_inputs, non_in = (uint32_t)net->n_nodes - n_in, p, t, k;
    uint16_t *placed = (uint16_t *)(void *)net->act[0];

    for (t = 0; t < net->n_nodes; t++)
        placed[t] = (uint16_t)(t < n_in);
    for (p = 0; p < non_in; p++) {
        uint32_t pick = non_in, first = non_in;
        for (t = 0; t < non_in; t++) {
            if (placed[n_in + t])
                continue;
            if (first == non_in)
                first = t;
            for (k = t ? net->end[t - 1u] : 0u; k < net->end[t]; k++)
                if (net->src[k] != n_in + t && !placed[net->src[k]])
                    break;
            if (k == net->end[t]) {
                pick = t;
                break;
            }
        }
        if (pick == non_in)
            pick = first; /* only cycles left: its unplaced sources read the previous step */
        net->order[p] = (uint8_t)(n_in + pick);
        placed[n_in + pick] = 1;
    }
}
#endif

int nrt_load(nrt_net *net, const uint8_t *blob, size_t len, void *mem, size_t mem_len)
{
    size_t total, need;
    uint32_t crc, k, n_conns, n_in, nodes, prev_dst = 0;
    uint16_t j;
    uint8_t *m;
    int err;

    if (net == NULL)
        return NRT_E_ARG;
    memset(net, 0, sizeof *net);
    if (mem == NULL)
        return NRT_E_ARG;
    err = nrt_inspect(blob, len, &total, &need);
    if (err != NRT_OK)
        return err;
    if (len < total)
        return NRT_E_TRUNCATED;
    if (len > total)
        return NRT_E_TRAILING;
    crc = nrt_crc32(0, blob, NRT_OFF_CRC);
    crc = nrt_crc32(crc, blob + NRT_HEADER_SIZE, total - NRT_HEADER_SIZE);
    if (crc != nrt_rd32(blob + NRT_OFF_CRC))
        return NRT_E_CRC;

    n_in = nrt_rd16(blob + NRT_OFF_INPUTS);
    n_conns = nrt_rd16(blob + NRT_OFF_CONNS);
    nodes = n_in + nrt_rd16(blob + NRT_OFF_OUTPUTS) + nrt_rd16(blob + NRT_OFF_HIDDEN);
    for (k = 0; k < n_conns; k++) {
        const uint8_t *c = blob + NRT_HEADER_SIZE + NRT_CONN_SIZE * k;
        if (c[0] >= nodes || c[1] < n_in || c[1] >= nodes)
            return NRT_E_INDEX;
        if (c[1] < prev_dst)
            return NRT_E_ORDER;
        if (nrt_rd16(c + 2) == 0x8000u)
            return NRT_E_WEIGHT;
        prev_dst = c[1];
    }
    if (mem_len < need)
        return NRT_E_NOMEM;

    /* Everything checked: lay out the buffer (16-bit arrays, 2-aligned). */
    net->n_inputs = (uint16_t)n_in;
    net->n_outputs = nrt_rd16(blob + NRT_OFF_OUTPUTS);
    net->n_hidden = nrt_rd16(blob + NRT_OFF_HIDDEN);
    net->n_nodes = (uint16_t)nodes;
    net->n_conns = (uint16_t)n_conns;
    m = (uint8_t *)mem;
    m += (uintptr_t)m & 1u;
    net->weight = (nrt_w12 *)(void *)m;
    m += 2u * n_conns;
    net->src = (uint16_t *)(void *)m;
    m += 2u * n_conns;
    net->end = (uint16_t *)(void *)m;
    m += 2u * (nodes - n_in);
    net->act[0] = (nrt_q15 *)(void *)m;
    m += 2u * nodes;
    net->act[1] = (nrt_q15 *)(void *)m;

    for (j = 0; j < nodes - n_in; j++)
        net->end[j] = 0;
    for (k = 0; k < n_conns; k++) {
        const uint8_t *c = blob + NRT_HEADER_SIZE + NRT_CONN_SIZE * k;
        net->weight[k] = (nrt_w12)nrt_rd16(c + 2);
        net->src[k] = c[0];
        net->end[c[1] - n_in] = (uint16_t)(k + 1);
    }
    /* a node with no incoming connection ends where the previous one did */
    for (j = 1; j < nodes - n_in; j++)
        if (net->end[j] < net->end[j - 1])
            net->end[j] = net->end[j - 1];
#ifndef NRT_NO_PROPAGATE
    net->step = blob[NRT_OFF_STEP];
    if (net->step == NRT_STEP_PROPAGATE) {
        net->order = (uint8_t *)(net->act[1] + nodes);
        nrt_order(net);
    }
#endif
    nrt_reset(net);
    return NRT_OK;
}

#ifndef NRT_NO_STRERROR
const char *nrt_strerror(int err)
{
    switch (err) {
    case NRT_OK: return "ok";
    case NRT_E_ARG: return "invalid argument";
    case NRT_E_TRUNCATED: return "blob truncated";
    case NRT_E_MAGIC: return "not a champion blob (bad magic)";
    case NRT_E_VERSION: return "unknown blob format version";
    case NRT_E_HEADER: return "bad blob header (size, weight format, activation or reserved bytes)";
    case NRT_E_COUNTS: return "impossible node or connection counts";
    case NRT_E_CRC: return "checksum mismatch";
    case NRT_E_INDEX: return "connection refers to a node out of range or into an input";
    case NRT_E_ORDER: return "connections not sorted by target node";
    case NRT_E_NOMEM: return "buffer too small for this network";
    case NRT_E_TRAILING: return "bytes after the end of the blob";
    case NRT_E_WEIGHT: return "weight -32768 outside the symmetric Q3.12 range";
    default: return "unknown error";
    }
}
#endif
