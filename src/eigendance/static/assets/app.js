(function(){const e=document.createElement("link").relList;if(e&&e.supports&&e.supports("modulepreload"))return;for(const i of document.querySelectorAll('link[rel="modulepreload"]'))a(i);new MutationObserver(i=>{for(const r of i)if(r.type==="childList")for(const s of r.addedNodes)s.tagName==="LINK"&&s.rel==="modulepreload"&&a(s)}).observe(document,{childList:!0,subtree:!0});function t(i){const r={};return i.integrity&&(r.integrity=i.integrity),i.referrerPolicy&&(r.referrerPolicy=i.referrerPolicy),i.crossOrigin==="use-credentials"?r.credentials="include":i.crossOrigin==="anonymous"?r.credentials="omit":r.credentials="same-origin",r}function a(i){if(i.ep)return;i.ep=!0;const r=t(i);fetch(i.href,r)}})();let oi=null;function sf(n){if(!oi){oi=new Float32Array(65536);for(let e=0;e<65536;e++){const t=e&32768?-1:1,a=e>>10&31,i=e&1023;oi[e]=a===0?t*i*2**-24:a===31?i?NaN:t*(1/0):t*(1+i/1024)*2**(a-15)}}return oi[n]}function _i(n){const e=new Uint8Array(n);if(e.length<8||String.fromCharCode(...e.subarray(0,4))!=="EDB1")throw new Error("not an eigendance bundle");const t=new DataView(n).getUint32(4,!0),a=JSON.parse(new TextDecoder().decode(e.subarray(8,8+t))),i=8+t,r={};for(const[s,o]of Object.entries(a.arrays)){const c=o.shape.reduce((f,b)=>f*b,1),l=i+o.offset,h=o.dtype==="float16"||o.dtype==="uint16"?2:o.dtype==="uint8"?1:4;if(l+h*c>n.byteLength)throw new Error(`bundle array ${s} truncated`);if(o.dtype==="float16"){const f=new Uint16Array(n,l,c),b=new Float32Array(c);sf(0);for(let p=0;p<c;p++)b[p]=oi[f[p]];r[s]={data:b,shape:o.shape};continue}const d=o.dtype==="uint32"?Uint32Array:o.dtype==="uint16"?Uint16Array:o.dtype==="uint8"?Uint8Array:Float32Array;r[s]={data:new d(n,l,c),shape:o.shape}}return{meta:a.meta,arrays:r}}function Fr(n){return n.reduced?n.reduced.m:n.n}function of(n){const e=n.arrays,t=e.vertices.shape[0],a=e.eigenvalues.shape[0],i=e.harmonics??e.coarse;return{name:n.meta.name??"mesh",n:t,k:a,k4:i.shape[1]/4,vertices:e.vertices.data,faces:e.faces.data,eigenvalues:e.eigenvalues.data,coefficients:e.coefficients.data,harmonics:i.data,reduced:e.coarse?{m:e.coarse.shape[0],asked:n.meta.samples??null,weights:e.weights.data,indices:e.indices.data}:void 0}}function cf(n){const e=n.arrays;return{name:n.meta.name??"song",rate:n.meta.rate,frames:e.values.shape[0],bands:e.values.shape[1],duration:n.meta.duration,times:e.times.data,values:e.values.data,bandEdges:e.band_edges.data,beats:e.beats?.data??new Float32Array(0),onsets:e.onsets?.data??new Float32Array(0),downbeats:e.downbeats?.data??new Float32Array(0),sections:e.sections?.data??new Float32Array(0),tempo:n.meta.tempo??0,meter:n.meta.meter??0}}async function Bt(n){if(!n.ok){let e=`${n.status} ${n.statusText}`;try{e=(await n.json()).error??e}catch{}throw new Error(e)}return n}async function ia(n){return(await Bt(await fetch(n))).json()}async function cn(n,e){return(await Bt(await fetch(n,{method:"POST",headers:{"Content-Type":"application/json"},body:JSON.stringify(e)}))).json()}const yl=()=>ia("api/library"),hf=()=>ia("api/config");async function lf(n,e=!1){const a=await Bt(await fetch(`api/meshes/${n}/basis.bin${e?"?dtype=float16":""}`));return of(_i(await a.arrayBuffer()))}async function df(n){const e=await Bt(await fetch(`api/songs/${n}/spectrogram.bin`));return cf(_i(await e.arrayBuffer()))}async function ff(n){return(await Bt(await fetch(`api/songs/${n}/audio`))).arrayBuffer()}async function uf(n,e,t){return(await cn("api/gallery",t===null?{mesh:n,song:e}:{mesh:n,song:e,size:t})).mappings}async function xl(n,e,t,a=null){return(await cn("api/breed",{parents:n,size:e,seed:t,...a??{}})).mappings}async function bf(n,e){const t=n==="mesh"?"meshes":`${n}s`;return(await(await Bt(await fetch(`api/${t}/${encodeURIComponent(e)}`,{method:"DELETE"}))).json()).removed}async function mf(n){const e=await fetch(`api/upload?name=${encodeURIComponent(n.name)}`,{method:"POST",body:n,headers:{"Content-Type":"application/octet-stream"}});return(await Bt(e)).json()}function To(n,e){return new Promise((t,a)=>{const i=new EventSource(`api/jobs/${n}/events`);i.onmessage=r=>{const s=JSON.parse(r.data);e(s),s.state==="done"&&(i.close(),t(s)),s.state==="error"&&(i.close(),a(new Error(s.message)))},i.onerror=()=>{i.close(),ia(`api/jobs/${n}`).then(r=>{r.state==="done"?t(r):r.state==="error"?a(new Error(r.message)):To(n,e).then(t,a)},a)}})}async function pf(n,e){const t=await fetch(`api/takes?name=${encodeURIComponent(e)}`,{method:"POST",body:n});return(await Bt(t)).json()}function I(n){return document.getElementById(n)}function ko(n,e){const t=document.createElement("a");t.href=URL.createObjectURL(n),t.download=e,t.click(),setTimeout(()=>URL.revokeObjectURL(t.href),1e3)}function Wa(n,e,t){const a=(r,s)=>r.replace(s,"-").replace(/^-+|-+$/g,"");return`${[a(n.replace(/\.[^.]*$/,""),/[^\w-]+/g)||"dance",a(e,/[^\w.-]+/g)].filter(Boolean).join("-")}.${t}`}function Ei(n,e){ko(new Blob([JSON.stringify(n,null,1)],{type:"application/json"}),e)}function wa(n){return n instanceof Error?n.message:String(n)}const wl=15,gf="a live input plays, not a song: “save take” keeps what was heard as one; choose it in the song menu to export its dance";function lc(n,e,t){const a=Number.isFinite(n)?n:0,i=Math.max(0,Math.min(a,Math.max(0,t-.1))),r=Number.isFinite(e)&&e>0?e:wl;return{start:Math.round(i*100)/100,duration:Math.round(Math.max(.1,Math.min(r,t-i))*100)/100}}function vf(n,e,t,a){const i=`${Math.floor(e/60)}m${String(Math.floor(e%60)).padStart(2,"0")}s`;return Wa(n,`${i}-${+t.toFixed(1)}s`,a)}class yf{constructor(e,t){this.messages=e,this.events=t;for(const a of["export-open","rig-export-open"])I(a).addEventListener("click",()=>this.toggle());I("export-close").addEventListener("click",()=>{I("export-panel").hidden=!0}),I("export-start-now").addEventListener("click",()=>this.fill()),I("export-go").addEventListener("click",()=>{this.run()}),I("export-format").addEventListener("change",()=>this.refresh())}messages;events;running=!1;made="";toggle(){const e=I("export-panel");if(e.hidden&&this.events.dance()===null){this.messages.status("open a tile in the player to export it");return}e.hidden=!e.hidden,e.hidden||this.fill()}fill(){const{start:e,duration:t}=lc(this.events.now(),wl,this.events.duration());I("export-start").value=e.toFixed(1),I("export-duration").value=t.toFixed(1),this.refresh()}refresh(){const e=this.events.dance(),t=this.events.live(),a=I("export-go");a.disabled=this.running||e===null||t,I("export-what").textContent=t?gf:e?`${e.name}, the player's mapping`:"open a tile in the player to export it",!this.running&&this.made!==dc(e)&&(I("export-download").hidden=!0,I("export-state").textContent=""),I("export-size-label").hidden=I("export-format").value!=="mp4",e===null&&!this.running&&(I("export-panel").hidden=!0)}request(){const e=this.events.dance();if(!e)return null;const{start:t,duration:a}=lc(Number(I("export-start").value),Number(I("export-duration").value),this.events.duration()),i=I("export-format").value;return{[e.kind]:e.id,song:e.song,mapping:e.mapping,format:i,start:t,duration:a,...i==="mp4"?{size:I("export-size").value}:{}}}async run(){const e=this.request(),t=this.events.dance();if(!e||!t||this.running||this.events.live()){this.refresh();return}this.running=!0,this.refresh();const a=I("export-progress"),i=I("export-download");i.hidden=!0,this.made="",a.hidden=!1,a.removeAttribute("value");const r=o=>{I("export-state").textContent=o};r("starting…"),await this.messages.guard("The export failed",async()=>{const{job:o}=await cn("api/export",e);await To(o.id,l=>{l.total&&(a.value=l.done/l.total),r(l.state==="queued"?"waiting for the renderer…":`${l.done} of ${l.total} frames`)});const c=await(await Bt(await fetch(`api/exports/${o.id}`))).blob();i.href.startsWith("blob:")&&URL.revokeObjectURL(i.href),i.href=URL.createObjectURL(c),i.download=vf(t.name,e.start,e.duration,e.format),i.textContent=`download ${i.download}`,i.hidden=!1,this.made=dc(t),r("done"),i.click()})&&r("failed (see the message above)"),a.hidden=!0,this.running=!1,this.refresh()}}function dc(n){return n?JSON.stringify([n.kind,n.id,n.song,n.mapping]):""}var St=Uint8Array,Ot=Uint16Array,Ro=Int32Array,Co=new St([0,0,0,0,0,0,0,0,1,1,1,1,2,2,2,2,3,3,3,3,4,4,4,4,5,5,5,5,0,0,0,0]),Io=new St([0,0,0,0,1,1,2,2,3,3,4,4,5,5,6,6,7,7,8,8,9,9,10,10,11,11,12,12,13,13,0,0]),fc=new St([16,17,18,0,8,7,9,6,10,5,11,4,12,3,13,2,14,1,15]),Ml=function(n,e){for(var t=new Ot(31),a=0;a<31;++a)t[a]=e+=1<<n[a-1];for(var i=new Ro(t[30]),a=1;a<30;++a)for(var r=t[a];r<t[a+1];++r)i[r]=r-t[a]<<5|a;return{b:t,r:i}},_l=Ml(Co,2),xf=_l.b,Ts=_l.r;xf[28]=258,Ts[258]=28;var wf=Ml(Io,0),uc=wf.r,ks=new Ot(32768);for(var st=0;st<32768;++st){var Ca=(st&43690)>>1|(st&21845)<<1;Ca=(Ca&52428)>>2|(Ca&13107)<<2,Ca=(Ca&61680)>>4|(Ca&3855)<<4,ks[st]=((Ca&65280)>>8|(Ca&255)<<8)>>1}var ui=(function(n,e,t){for(var a=n.length,i=0,r=new Ot(e);i<a;++i)n[i]&&++r[n[i]-1];var s=new Ot(e);for(i=1;i<e;++i)s[i]=s[i-1]+r[i-1]<<1;var o;if(t){o=new Ot(1<<e);var c=15-e;for(i=0;i<a;++i)if(n[i])for(var l=i<<4|n[i],h=e-n[i],d=s[n[i]-1]++<<h,f=d|(1<<h)-1;d<=f;++d)o[ks[d]>>c]=l}else for(o=new Ot(a),i=0;i<a;++i)n[i]&&(o[i]=ks[s[n[i]-1]++]>>15-n[i]);return o}),rn=new St(288);for(var st=0;st<144;++st)rn[st]=8;for(var st=144;st<256;++st)rn[st]=9;for(var st=256;st<280;++st)rn[st]=7;for(var st=280;st<288;++st)rn[st]=8;var mr=new St(32);for(var st=0;st<32;++st)mr[st]=5;var Mf=ui(rn,9,0),_f=ui(mr,5,0),El=function(n){return(n+7)/8|0},Sl=function(n,e,t){return(t==null||t>n.length)&&(t=n.length),new St(n.subarray(e,t))},Ef=["unexpected EOF","invalid block type","invalid length/literal","invalid distance","stream finished","no stream handler",,"no callback","invalid UTF-8 data","extra field too long","date not in range 1980-2099","filename too long","stream finishing","invalid zip data"],Ar=function(n,e,t){var a=new Error(e||Ef[n]);if(a.code=n,Error.captureStackTrace&&Error.captureStackTrace(a,Ar),!t)throw a;return a},la=function(n,e,t){t<<=e&7;var a=e/8|0;n[a]|=t,n[a+1]|=t>>8},Jn=function(n,e,t){t<<=e&7;var a=e/8|0;n[a]|=t,n[a+1]|=t>>8,n[a+2]|=t>>16},Lr=function(n,e){for(var t=[],a=0;a<n.length;++a)n[a]&&t.push({s:a,f:n[a]});var i=t.length,r=t.slice();if(!i)return{t:Tl,l:0};if(i==1){var s=new St(t[0].s+1);return s[t[0].s]=1,{t:s,l:1}}t.sort(function(E,_){return E.f-_.f}),t.push({s:-1,f:25001});var o=t[0],c=t[1],l=0,h=1,d=2;for(t[0]={s:-1,f:o.f+c.f,l:o,r:c};h!=i-1;)o=t[t[l].f<t[d].f?l++:d++],c=t[l!=h&&t[l].f<t[d].f?l++:d++],t[h++]={s:-1,f:o.f+c.f,l:o,r:c};for(var f=r[0].s,a=1;a<i;++a)r[a].s>f&&(f=r[a].s);var b=new Ot(f+1),p=Rs(t[h-1],b,0);if(p>e){var a=0,g=0,m=p-e,u=1<<m;for(r.sort(function(_,A){return b[A.s]-b[_.s]||_.f-A.f});a<i;++a){var y=r[a].s;if(b[y]>e)g+=u-(1<<p-b[y]),b[y]=e;else break}for(g>>=m;g>0;){var x=r[a].s;b[x]<e?g-=1<<e-b[x]++-1:++a}for(;a>=0&&g;--a){var v=r[a].s;b[v]==e&&(--b[v],++g)}p=e}return{t:new St(b),l:p}},Rs=function(n,e,t){return n.s==-1?Math.max(Rs(n.l,e,t+1),Rs(n.r,e,t+1)):e[n.s]=t},bc=function(n){for(var e=n.length;e&&!n[--e];);for(var t=new Ot(++e),a=0,i=n[0],r=1,s=function(c){t[a++]=c},o=1;o<=e;++o)if(n[o]==i&&o!=e)++r;else{if(!i&&r>2){for(;r>138;r-=138)s(32754);r>2&&(s(r>10?r-11<<5|28690:r-3<<5|12305),r=0)}else if(r>3){for(s(i),--r;r>6;r-=6)s(8304);r>2&&(s(r-3<<5|8208),r=0)}for(;r--;)s(i);r=1,i=n[o]}return{c:t.subarray(0,a),n:e}},Yn=function(n,e){for(var t=0,a=0;a<e.length;++a)t+=n[a]*e[a];return t},Al=function(n,e,t){var a=t.length,i=El(e+2);n[i]=a&255,n[i+1]=a>>8,n[i+2]=n[i]^255,n[i+3]=n[i+1]^255;for(var r=0;r<a;++r)n[i+r+4]=t[r];return(i+4+a)*8},mc=function(n,e,t,a,i,r,s,o,c,l,h){la(e,h++,t),++i[256];for(var d=Lr(i,15),f=d.t,b=d.l,p=Lr(r,15),g=p.t,m=p.l,u=bc(f),y=u.c,x=u.n,v=bc(g),E=v.c,_=v.n,A=new Ot(19),k=0;k<y.length;++k)++A[y[k]&31];for(var k=0;k<E.length;++k)++A[E[k]&31];for(var w=Lr(A,7),M=w.t,R=w.l,U=19;U>4&&!M[fc[U-1]];--U);var P=l+5<<3,D=Yn(i,rn)+Yn(r,mr)+s,V=Yn(i,f)+Yn(r,g)+s+14+3*U+Yn(A,M)+2*A[16]+3*A[17]+7*A[18];if(c>=0&&P<=D&&P<=V)return Al(e,h,n.subarray(c,c+l));var B,G,z,Y;if(la(e,h,1+(V<D)),h+=2,V<D){B=ui(f,b,0),G=f,z=ui(g,m,0),Y=g;var te=ui(M,R,0);la(e,h,x-257),la(e,h+5,_-1),la(e,h+10,U-4),h+=14;for(var k=0;k<U;++k)la(e,h+3*k,M[fc[k]]);h+=3*U;for(var ie=[y,E],pe=0;pe<2;++pe)for(var Te=ie[pe],k=0;k<Te.length;++k){var W=Te[k]&31;la(e,h,te[W]),h+=M[W],W>15&&(la(e,h,Te[k]>>5&127),h+=Te[k]>>12)}}else B=Mf,G=rn,z=_f,Y=mr;for(var k=0;k<o;++k){var J=a[k];if(J>255){var W=J>>18&31;Jn(e,h,B[W+257]),h+=G[W+257],W>7&&(la(e,h,J>>23&31),h+=Co[W]);var se=J&31;Jn(e,h,z[se]),h+=Y[se],se>3&&(Jn(e,h,J>>5&8191),h+=Io[se])}else Jn(e,h,B[J]),h+=G[J]}return Jn(e,h,B[256]),h+G[256]},Sf=new Ro([65540,131080,131088,131104,262176,1048704,1048832,2114560,2117632]),Tl=new St(0),Af=function(n,e,t,a,i,r){var s=r.z||n.length,o=new St(a+s+5*(1+Math.ceil(s/7e3))+i),c=o.subarray(a,o.length-i),l=r.l,h=(r.r||0)&7;if(e){h&&(c[0]=r.r>>3);for(var d=Sf[e-1],f=d>>13,b=d&8191,p=(1<<t)-1,g=r.p||new Ot(32768),m=r.h||new Ot(p+1),u=Math.ceil(t/3),y=2*u,x=function(F){return(n[F]^n[F+1]<<u^n[F+2]<<y)&p},v=new Ro(25e3),E=new Ot(288),_=new Ot(32),A=0,k=0,w=r.i||0,M=0,R=r.w||0,U=0;w+2<s;++w){var P=x(w),D=w&32767,V=m[P];if(g[D]=V,m[P]=D,R<=w){var B=s-w;if((A>7e3||M>24576)&&(B>423||!l)){h=mc(n,c,0,v,E,_,k,M,U,w-U,h),M=A=k=0,U=w;for(var G=0;G<286;++G)E[G]=0;for(var G=0;G<30;++G)_[G]=0}var z=2,Y=0,te=b,ie=D-V&32767;if(B>2&&P==x(w-ie))for(var pe=Math.min(f,B)-1,Te=Math.min(32767,w),W=Math.min(258,B);ie<=Te&&--te&&D!=V;){if(n[w+z]==n[w+z-ie]){for(var J=0;J<W&&n[w+J]==n[w+J-ie];++J);if(J>z){if(z=J,Y=ie,J>pe)break;for(var se=Math.min(ie,J-2),re=0,G=0;G<se;++G){var ge=w-ie+G&32767,Ae=g[ge],Re=ge-Ae&32767;Re>re&&(re=Re,V=ge)}}}D=V,V=g[D],ie+=D-V&32767}if(Y){v[M++]=268435456|Ts[z]<<18|uc[Y];var We=Ts[z]&31,Ie=uc[Y]&31;k+=Co[We]+Io[Ie],++E[257+We],++_[Ie],R=w+z,++A}else v[M++]=n[w],++E[n[w]]}}for(w=Math.max(w,R);w<s;++w)v[M++]=n[w],++E[n[w]];h=mc(n,c,l,v,E,_,k,M,U,w-U,h),l||(r.r=h&7|c[h/8|0]<<3,h-=7,r.h=m,r.p=g,r.i=w,r.w=R)}else{for(var w=r.w||0;w<s+l;w+=65535){var Ke=w+65535;Ke>=s&&(c[h/8|0]=l,Ke=s),h=Al(c,h+1,n.subarray(w,Ke))}r.i=s}return Sl(o,0,a+El(h)+i)},Tf=(function(){for(var n=new Int32Array(256),e=0;e<256;++e){for(var t=e,a=9;--a;)t=(t&1&&-306674912)^t>>>1;n[e]=t}return n})(),kf=function(){var n=-1;return{p:function(e){for(var t=n,a=0;a<e.length;++a)t=Tf[t&255^e[a]]^t>>>8;n=t},d:function(){return~n}}},Rf=function(n,e,t,a,i){if(!i&&(i={l:1},e.dictionary)){var r=e.dictionary.subarray(-32768),s=new St(r.length+n.length);s.set(r),s.set(n,r.length),n=s,i.w=r.length}return Af(n,e.level==null?6:e.level,e.mem==null?i.l?Math.ceil(Math.max(8,Math.min(13,Math.log(n.length)))*1.5):20:12+e.mem,t,a,i)},kl=function(n,e){var t={};for(var a in n)t[a]=n[a];for(var a in e)t[a]=e[a];return t},gt=function(n,e,t){for(;t;++e)n[e]=t,t>>>=8};function Cf(n,e){return Rf(n,e||{},0,0)}var Rl=function(n,e,t,a){for(var i in n){var r=n[i],s=e+i,o=a;Array.isArray(r)&&(o=kl(a,r[1]),r=r[0]),r instanceof St?t[s]=[r,o]:(t[s+="/"]=[new St(0),o],Rl(r,s,t,a))}},pc=typeof TextEncoder<"u"&&new TextEncoder,If=typeof TextDecoder<"u"&&new TextDecoder,Pf=0;try{If.decode(Tl,{stream:!0}),Pf=1}catch{}function gc(n,e){var t;if(pc)return pc.encode(n);for(var a=n.length,i=new St(n.length+(n.length>>1)),r=0,s=function(l){i[r++]=l},t=0;t<a;++t){if(r+5>i.length){var o=new St(r+8+(a-t<<1));o.set(i),i=o}var c=n.charCodeAt(t);c<128||e?s(c):c<2048?(s(192|c>>6),s(128|c&63)):c>55295&&c<57344?(c=65536+(c&1047552)|n.charCodeAt(++t)&1023,s(240|c>>18),s(128|c>>12&63),s(128|c>>6&63),s(128|c&63)):(s(224|c>>12),s(128|c>>6&63),s(128|c&63))}return Sl(i,0,r)}var Cs=function(n){var e=0;if(n)for(var t in n){var a=n[t].length;a>65535&&Ar(9),e+=a+4}return e},vc=function(n,e,t,a,i,r,s,o){var c=a.length,l=t.extra,h=o&&o.length,d=Cs(l);gt(n,e,s!=null?33639248:67324752),e+=4,s!=null&&(n[e++]=20,n[e++]=t.os),n[e]=20,e+=2,n[e++]=t.flag<<1|(r<0&&8),n[e++]=i&&8,n[e++]=t.compression&255,n[e++]=t.compression>>8;var f=new Date(t.mtime==null?Date.now():t.mtime),b=f.getFullYear()-1980;if((b<0||b>119)&&Ar(10),gt(n,e,b<<25|f.getMonth()+1<<21|f.getDate()<<16|f.getHours()<<11|f.getMinutes()<<5|f.getSeconds()>>1),e+=4,r!=-1&&(gt(n,e,t.crc),gt(n,e+4,r<0?-r-2:r),gt(n,e+8,t.size)),gt(n,e+12,c),gt(n,e+14,d),e+=16,s!=null&&(gt(n,e,h),gt(n,e+6,t.attrs),gt(n,e+10,s),e+=14),n.set(a,e),e+=c,d)for(var p in l){var g=l[p],m=g.length;gt(n,e,+p),gt(n,e+2,m),n.set(g,e+4),e+=4+m}return h&&(n.set(o,e),e+=h),e},Df=function(n,e,t,a,i){gt(n,e,101010256),gt(n,e+8,t),gt(n,e+10,t),gt(n,e+12,a),gt(n,e+16,i)};function Nf(n,e){e||(e={});var t={},a=[];Rl(n,"",t,e);var i=0,r=0;for(var s in t){var o=t[s],c=o[0],l=o[1],h=l.level==0?0:8,d=gc(s),f=d.length,b=l.comment,p=b&&gc(b),g=p&&p.length,m=Cs(l.extra);f>65535&&Ar(11);var u=h?Cf(c,l):c,y=u.length,x=kf();x.p(c),a.push(kl(l,{size:c.length,crc:x.d(),c:u,f:d,m:p,u:f!=s.length||p&&b.length!=g,o:i,compression:h})),i+=30+f+m+y,r+=76+2*(f+m)+(g||0)+y}for(var v=new St(r+22),E=i,_=r-i,A=0;A<a.length;++A){var d=a[A];vc(v,d.o,d,d.f,d.u,d.c.length);var k=30+d.f.length+Cs(d.extra);v.set(d.c,d.o+k),vc(v,i,d,d.f,d.u,d.c.length,d.o,d.m),i+=16+k+(d.m?d.m.length:0)}return Df(v,i,a.length,_,E),v}class Uf{constructor(e,t){this.messages=e,this.events=t}messages;events;suffixes=null;async handle(e,t){for(const a of await jf(Array.from(e),this.suffixes,t))try{await this.add(a)}catch(i){this.messages.status(""),this.messages.error(`${a.name} could not be added: `+Ff(wa(i),a.name))}}wire(){I("upload").addEventListener("change",t=>{const a=t.target;a.files&&this.handle(Array.from(a.files)),a.value=""});const e=I("drop");window.addEventListener("dragover",t=>{t.preventDefault(),e.hidden=!1}),e.addEventListener("dragleave",()=>{e.hidden=!0}),window.addEventListener("drop",t=>{if(t.preventDefault(),e.hidden=!0,!t.dataTransfer?.files.length)return;const a=Array.from(t.dataTransfer.items??[],i=>i.webkitGetAsEntry?.());a.some(i=>i?.isDirectory)?Of(a.filter(i=>!!i)).then(i=>this.handle(i.map(r=>r.file),i.map(r=>r.path))):this.handle(t.dataTransfer.files)})}async add(e){const{messages:t,events:a}=this;t.status(`adding ${e.name}…`),t.loading(`${e.name}: uploading…`);const i=await mf(e).finally(()=>t.loading(null));if(await a.refresh(),!a.started()){await a.startIfComplete()&&t.status(`${e.name} ready`);return}if(i.kind==="rig"||i.rig){if(await a.openRig(i.kind==="rig"?i.item.id:i.rig.id))return}else if(i.kind==="mesh"){if(await a.showMesh(i.item.id))return}else i.kind==="song"?await a.changeSong(i.item.id):i.kind==="mapping"&&(I("mapping-menu").value=i.item.id,a.openMapping(i.item.id,await ia(`api/mappings/${i.item.id}`),e.name));t.status(`${i.item?.name??e.name} ready`),a.requestDraw()}}function Ff(n,e){return n.startsWith(`${e}: `)?n.slice(e.length+2):n}function Lf(n){const e=n?.suffixes,t=["mesh","rig","audio","mapping","archive","companion"],a=i=>Array.isArray(i)&&i.every(r=>typeof r=="string");return e&&t.every(i=>a(e[i]))?e:null}function yc(n){const e=n.lastIndexOf(".");return e<0?"":n.slice(e).toLowerCase()}async function jf(n,e,t){if(e===null)return n;const a=h=>e.mesh.includes(yc(h.name)),i=h=>e.companion.includes(yc(h.name)),r=n.filter(a),s=n.filter(i);if(!r.length||!s.length)return n;const o={};for(const[h,d]of n.entries()){if(!a(d)&&!i(d))continue;const f=(t?.[h]??d.name).replace(/^\/+/,"");o[f]=new Uint8Array(await d.arrayBuffer())}const c=r[0].name.replace(/\.[^.]*$/,"")+".zip",l=Nf(o,{level:0});return[new File([l],c,{type:"application/zip"}),...n.filter(h=>!a(h)&&!i(h))]}async function Of(n){const e=[],t=async a=>{if(a.isFile){const i=await new Promise((r,s)=>a.file(r,s));e.push({file:i,path:a.fullPath})}else if(a.isDirectory){const i=a.createReader();for(;;){const r=await new Promise((s,o)=>i.readEntries(s,o));if(!r.length)break;for(const s of r)await t(s)}}};for(const a of n)await t(a);return e}const zf=4;function Bf(n){const e=n===null||n.trim()===""?NaN:Number(n);return Number.isFinite(e)&&e>=.1&&e<=1?e:null}const Gf=1,Hf=120;function Vf(n){const e=n===null||n.trim()===""?NaN:Number(n);return Number.isFinite(e)&&e>=Gf&&e<=Hf?e:null}function Wf(n){const e=new URLSearchParams(n),t=e.get("path");return{size:e.get("size"),mesh:e.get("mesh"),song:e.get("song"),mapping:e.get("mapping"),view:e.get("view")==="player"?"player":e.get("view")==="gallery"?"gallery":null,aa:e.has("aa")?e.get("aa")!=="0":null,half:e.has("half")?e.get("half")!=="0":null,render:e.has("render"),test:e.has("test"),bare:e.has("bare"),path:t==="gpu"||t==="cpu"?t:null,batch:Number(e.get("batch")??8),scale:Bf(e.get("scale")),fps:Vf(e.get("fps")),source:e.get("source")==="mic"?"mic":e.get("source")==="tab"?"tab":null,badSource:e.has("source")&&!["mic","tab"].includes(e.get("source"))?e.get("source"):null}}const xc=n=>n.render||n.test;function qf(n){const e=n?.gallery,{min:t,max:a,default:i}=e??{},r=s=>Number.isInteger(s);if(!r(t)||!r(a)||!r(i)||t<1||t>i||i>a)throw new Error("api/config: expected {gallery: {min, max, default}}, got "+JSON.stringify(n));return{min:t,max:a,default:i}}function Xf(n,e){const t=n!==null&&/^\s*\d+\s*$/.test(n)?Number(n):NaN;return e===null?{size:Number.isInteger(t)?t:null,problem:null}:n===null?{size:e.default,problem:null}:Number.isInteger(t)&&t>=e.min&&t<=e.max?{size:t,problem:null}:{size:e.default,problem:`?size=${n} is not a gallery size (an integer from ${e.min} to ${e.max}): showing ${e.default} tiles`}}function Kf(n,e){if(n===null)return[e];const t=[];for(let a=Math.max(zf,n.min);a<=n.max;a++)t.push(a);return t.includes(e)||t.push(e),t.sort((a,i)=>a-i)}function Jf(n,e,t,a){const i=Math.floor(n*e/t),r=Math.max(a,Math.min(n-1,i));return r<n?r:null}const Yf=3e3;class Zf{constructor(e){this.events=e,I("notice-close").addEventListener("click",()=>{this.hideNotice();const t=this.events.galleryTiles();t!==null&&this.dismissed.add(t)})}events;slowSince=null;tiles=null;dismissed=new Set;pending=!1;said=null;hideNotice(){I("notice").hidden=!0,this.slowSince=null}restart(){this.slowSince=null}update(e){const t=this.events.viewer(),{fps:a}=t,i=I("fps"),r=t.resolution.scale,s=t.resolution.detail;i.textContent=a>0?`${a.toFixed(a<10?1:0)} fps`+(r<1?` · ${Math.round(100*r)}%`:"")+(s<1?` · ${Math.round(100*s)}% △`:""):"";const o=t.resolution.describe();i.title="frames the page draws per second while the song plays"+(o?`; now ${o}`:"")+(s<1?" (△: of the triangles)":""),i.classList.toggle("slow",a>0&&a<t.resolution.rule.target),this.check(t,a,e),!I("notice").hidden&&a>0&&this.sayRate(a)}sayRate(e){if(!this.said)return;const{tiles:t,floor:a,target:i}=this.said;I("notice-text").textContent=`This page draws only ${e.toFixed(e<10?1:0)} frames per second with ${t} tiles${a} (it aims at ${i}).`}check(e,t,a){const i=this.events.galleryTiles();i!==this.tiles&&(this.tiles=i,this.slowSince=null,I("notice").hidden||this.hideNotice());const{target:r}=e.resolution.rule;if(!(i!==null&&!this.pending&&this.events.playing()&&t>0&&t<r&&(e.resolution.exhausted||!e.dynamic)&&!this.dismissed.has(i))){this.slowSince=null;return}if(this.slowSince??=a,a-this.slowSince<Yf||!I("notice").hidden)return;const o=Jf(i,t,r,this.events.smallest()),c=e.resolution.describe();this.said={tiles:i,target:r,floor:c?`, even ${c.replace(/ to keep .*/,"")}`:""},this.sayRate(t);const l=I("notice-fewer");l.hidden=o===null,l.textContent=`show ${o} tiles`,l.onclick=()=>{this.hideNotice(),o!==null&&(this.pending=!0,this.events.newGallery(o).finally(()=>{this.pending=!1,this.slowSince=null}))},I("notice").hidden=!1}}function Cl(n){let e=Math.max(1,Math.min(n,Math.ceil(Math.sqrt(n*1.5))));for(;e>1&&!(2*(n-(Math.ceil(n/e)-1)*e)>=e);)e--;return e}function Qf(n,e,t,a,i=6,r=18){if(!(e>0&&t>0&&a>0)||n<1)return Cl(n);let s=1,o=-1;for(let c=1;c<=n;c++){const l=Math.ceil(n/c);if(c>1&&2*(n-(l-1)*c)<c)continue;const h=(e-(c-1)*i)/c,d=(t-(l-1)*i)/l-r,f=Math.min(h/a,d);f>o*1.001&&(s=c,o=f)}return s}const $f=100,eu=64,tu=20,au=16e3,nu=-80,iu=.08,ru=.046,su={mel_bands:128,mel_fmax:11025,floor_db:-100,lag:.02,beat_sample_rate:22050,beat_hop:512,tempo_window:8},ou={downbeat_accent:.25},mt={rate:$f,bands:eu,fmin:tu,fmax:au,floor_db:nu,smoothing:iu,window_seconds:ru,onset:su,rhythm:ou};function Tr(n){return n.beats.length>=4&&n.tempo>0}function jr(n,e){const t=n.length;if(e<n[0])return(e-n[0])/(n[1]-n[0]);if(e>=n[t-1])return t-1+(e-n[t-1])/(n[t-1]-n[t-2]);let a=0,i=t-1;for(;i-a>1;){const r=a+i>>1;n[r]<=e?a=r:i=r}return a+(e-n[a])/(n[a+1]-n[a])}const cu=mt.rhythm.downbeat_accent;function Il(n,e){const{beats:t,downbeats:a}=n,i=jr(t,e);let r=1;if(n.meter>0&&a.length>=2){let s=0;for(;s<a.length&&a[s]<=e;)s++;s=Math.min(Math.max(s,1),a.length-1);const o=Math.min(Math.abs(i-jr(t,a[s-1])),Math.abs(i-jr(t,a[s])));o<1&&(r+=cu*Math.cos(Math.PI*o/2)**2)}return{phase:i,tempo:n.tempo,accent:r}}const Po="170",In={ROTATE:0,DOLLY:1,PAN:2},kn={ROTATE:0,PAN:1,DOLLY_PAN:2,DOLLY_ROTATE:3},hu=0,wc=1,lu=2,Pl=1,du=2,pa=3,Ma=0,Ut=1,Kt=2,Ga=0,Pn=1,Mc=2,_c=3,Ec=4,fu=5,en=100,uu=101,bu=102,mu=103,pu=104,gu=200,vu=201,yu=202,xu=203,Is=204,Ps=205,wu=206,Mu=207,_u=208,Eu=209,Su=210,Au=211,Tu=212,ku=213,Ru=214,Ds=0,Ns=1,Us=2,Un=3,Fs=4,Ls=5,js=6,Os=7,Dl=0,Cu=1,Iu=2,Ha=0,Pu=1,Du=2,Nu=3,Uu=4,Fu=5,Lu=6,ju=7,Sc="attached",zs="detached",Nl=300,Fn=301,Ln=302,Bs=303,Gs=304,kr=306,pr=1e3,za=1001,gr=1002,dt=1003,Ul=1004,ci=1005,na=1006,rr=1007,Ba=1008,_a=1009,Fl=1010,Ll=1011,vi=1012,Do=1013,sn=1014,zt=1015,Si=1016,No=1017,Uo=1018,jn=1020,jl=35902,Ol=1021,zl=1022,Rt=1023,Bl=1024,Gl=1025,Dn=1026,On=1027,Hl=1028,Fo=1029,Vl=1030,Lo=1031,jo=1033,sr=33776,or=33777,cr=33778,hr=33779,Hs=35840,Vs=35841,Ws=35842,qs=35843,Xs=36196,Ks=37492,Js=37496,Ys=37808,Zs=37809,Qs=37810,$s=37811,eo=37812,to=37813,ao=37814,no=37815,io=37816,ro=37817,so=37818,oo=37819,co=37820,ho=37821,lr=36492,lo=36494,fo=36495,Wl=36283,uo=36284,bo=36285,mo=36286,Ou=3200,zu=3201,Bu=0,Gu=1,ga="",kt="srgb",Hn="srgb-linear",Rr="linear",et="srgb",un=7680,Ac=519,Hu=512,Vu=513,Wu=514,ql=515,qu=516,Xu=517,Ku=518,Ju=519,po=35044,Xl=35048,Ea="300 es",va=2e3,vr=2001;class hn{addEventListener(e,t){this._listeners===void 0&&(this._listeners={});const a=this._listeners;a[e]===void 0&&(a[e]=[]),a[e].indexOf(t)===-1&&a[e].push(t)}hasEventListener(e,t){if(this._listeners===void 0)return!1;const a=this._listeners;return a[e]!==void 0&&a[e].indexOf(t)!==-1}removeEventListener(e,t){if(this._listeners===void 0)return;const i=this._listeners[e];if(i!==void 0){const r=i.indexOf(t);r!==-1&&i.splice(r,1)}}dispatchEvent(e){if(this._listeners===void 0)return;const a=this._listeners[e.type];if(a!==void 0){e.target=this;const i=a.slice(0);for(let r=0,s=i.length;r<s;r++)i[r].call(this,e);e.target=null}}}const xt=["00","01","02","03","04","05","06","07","08","09","0a","0b","0c","0d","0e","0f","10","11","12","13","14","15","16","17","18","19","1a","1b","1c","1d","1e","1f","20","21","22","23","24","25","26","27","28","29","2a","2b","2c","2d","2e","2f","30","31","32","33","34","35","36","37","38","39","3a","3b","3c","3d","3e","3f","40","41","42","43","44","45","46","47","48","49","4a","4b","4c","4d","4e","4f","50","51","52","53","54","55","56","57","58","59","5a","5b","5c","5d","5e","5f","60","61","62","63","64","65","66","67","68","69","6a","6b","6c","6d","6e","6f","70","71","72","73","74","75","76","77","78","79","7a","7b","7c","7d","7e","7f","80","81","82","83","84","85","86","87","88","89","8a","8b","8c","8d","8e","8f","90","91","92","93","94","95","96","97","98","99","9a","9b","9c","9d","9e","9f","a0","a1","a2","a3","a4","a5","a6","a7","a8","a9","aa","ab","ac","ad","ae","af","b0","b1","b2","b3","b4","b5","b6","b7","b8","b9","ba","bb","bc","bd","be","bf","c0","c1","c2","c3","c4","c5","c6","c7","c8","c9","ca","cb","cc","cd","ce","cf","d0","d1","d2","d3","d4","d5","d6","d7","d8","d9","da","db","dc","dd","de","df","e0","e1","e2","e3","e4","e5","e6","e7","e8","e9","ea","eb","ec","ed","ee","ef","f0","f1","f2","f3","f4","f5","f6","f7","f8","f9","fa","fb","fc","fd","fe","ff"];let Tc=1234567;const bi=Math.PI/180,yi=180/Math.PI;function oa(){const n=Math.random()*4294967295|0,e=Math.random()*4294967295|0,t=Math.random()*4294967295|0,a=Math.random()*4294967295|0;return(xt[n&255]+xt[n>>8&255]+xt[n>>16&255]+xt[n>>24&255]+"-"+xt[e&255]+xt[e>>8&255]+"-"+xt[e>>16&15|64]+xt[e>>24&255]+"-"+xt[t&63|128]+xt[t>>8&255]+"-"+xt[t>>16&255]+xt[t>>24&255]+xt[a&255]+xt[a>>8&255]+xt[a>>16&255]+xt[a>>24&255]).toLowerCase()}function Mt(n,e,t){return Math.max(e,Math.min(t,n))}function Oo(n,e){return(n%e+e)%e}function Yu(n,e,t,a,i){return a+(n-e)*(i-a)/(t-e)}function Zu(n,e,t){return n!==e?(t-n)/(e-n):0}function mi(n,e,t){return(1-t)*n+t*e}function Qu(n,e,t,a){return mi(n,e,1-Math.exp(-t*a))}function $u(n,e=1){return e-Math.abs(Oo(n,e*2)-e)}function eb(n,e,t){return n<=e?0:n>=t?1:(n=(n-e)/(t-e),n*n*(3-2*n))}function tb(n,e,t){return n<=e?0:n>=t?1:(n=(n-e)/(t-e),n*n*n*(n*(n*6-15)+10))}function ab(n,e){return n+Math.floor(Math.random()*(e-n+1))}function nb(n,e){return n+Math.random()*(e-n)}function ib(n){return n*(.5-Math.random())}function rb(n){n!==void 0&&(Tc=n);let e=Tc+=1831565813;return e=Math.imul(e^e>>>15,e|1),e^=e+Math.imul(e^e>>>7,e|61),((e^e>>>14)>>>0)/4294967296}function sb(n){return n*bi}function ob(n){return n*yi}function cb(n){return(n&n-1)===0&&n!==0}function hb(n){return Math.pow(2,Math.ceil(Math.log(n)/Math.LN2))}function lb(n){return Math.pow(2,Math.floor(Math.log(n)/Math.LN2))}function db(n,e,t,a,i){const r=Math.cos,s=Math.sin,o=r(t/2),c=s(t/2),l=r((e+a)/2),h=s((e+a)/2),d=r((e-a)/2),f=s((e-a)/2),b=r((a-e)/2),p=s((a-e)/2);switch(i){case"XYX":n.set(o*h,c*d,c*f,o*l);break;case"YZY":n.set(c*f,o*h,c*d,o*l);break;case"ZXZ":n.set(c*d,c*f,o*h,o*l);break;case"XZX":n.set(o*h,c*p,c*b,o*l);break;case"YXY":n.set(c*b,o*h,c*p,o*l);break;case"ZYZ":n.set(c*p,c*b,o*h,o*l);break;default:console.warn("THREE.MathUtils: .setQuaternionFromProperEuler() encountered an unknown order: "+i)}}function ta(n,e){switch(e.constructor){case Float32Array:return n;case Uint32Array:return n/4294967295;case Uint16Array:return n/65535;case Uint8Array:return n/255;case Int32Array:return Math.max(n/2147483647,-1);case Int16Array:return Math.max(n/32767,-1);case Int8Array:return Math.max(n/127,-1);default:throw new Error("Invalid component type.")}}function $e(n,e){switch(e.constructor){case Float32Array:return n;case Uint32Array:return Math.round(n*4294967295);case Uint16Array:return Math.round(n*65535);case Uint8Array:return Math.round(n*255);case Int32Array:return Math.round(n*2147483647);case Int16Array:return Math.round(n*32767);case Int8Array:return Math.round(n*127);default:throw new Error("Invalid component type.")}}const Kl={DEG2RAD:bi,RAD2DEG:yi,generateUUID:oa,clamp:Mt,euclideanModulo:Oo,mapLinear:Yu,inverseLerp:Zu,lerp:mi,damp:Qu,pingpong:$u,smoothstep:eb,smootherstep:tb,randInt:ab,randFloat:nb,randFloatSpread:ib,seededRandom:rb,degToRad:sb,radToDeg:ob,isPowerOfTwo:cb,ceilPowerOfTwo:hb,floorPowerOfTwo:lb,setQuaternionFromProperEuler:db,normalize:$e,denormalize:ta};class De{constructor(e=0,t=0){De.prototype.isVector2=!0,this.x=e,this.y=t}get width(){return this.x}set width(e){this.x=e}get height(){return this.y}set height(e){this.y=e}set(e,t){return this.x=e,this.y=t,this}setScalar(e){return this.x=e,this.y=e,this}setX(e){return this.x=e,this}setY(e){return this.y=e,this}setComponent(e,t){switch(e){case 0:this.x=t;break;case 1:this.y=t;break;default:throw new Error("index is out of range: "+e)}return this}getComponent(e){switch(e){case 0:return this.x;case 1:return this.y;default:throw new Error("index is out of range: "+e)}}clone(){return new this.constructor(this.x,this.y)}copy(e){return this.x=e.x,this.y=e.y,this}add(e){return this.x+=e.x,this.y+=e.y,this}addScalar(e){return this.x+=e,this.y+=e,this}addVectors(e,t){return this.x=e.x+t.x,this.y=e.y+t.y,this}addScaledVector(e,t){return this.x+=e.x*t,this.y+=e.y*t,this}sub(e){return this.x-=e.x,this.y-=e.y,this}subScalar(e){return this.x-=e,this.y-=e,this}subVectors(e,t){return this.x=e.x-t.x,this.y=e.y-t.y,this}multiply(e){return this.x*=e.x,this.y*=e.y,this}multiplyScalar(e){return this.x*=e,this.y*=e,this}divide(e){return this.x/=e.x,this.y/=e.y,this}divideScalar(e){return this.multiplyScalar(1/e)}applyMatrix3(e){const t=this.x,a=this.y,i=e.elements;return this.x=i[0]*t+i[3]*a+i[6],this.y=i[1]*t+i[4]*a+i[7],this}min(e){return this.x=Math.min(this.x,e.x),this.y=Math.min(this.y,e.y),this}max(e){return this.x=Math.max(this.x,e.x),this.y=Math.max(this.y,e.y),this}clamp(e,t){return this.x=Math.max(e.x,Math.min(t.x,this.x)),this.y=Math.max(e.y,Math.min(t.y,this.y)),this}clampScalar(e,t){return this.x=Math.max(e,Math.min(t,this.x)),this.y=Math.max(e,Math.min(t,this.y)),this}clampLength(e,t){const a=this.length();return this.divideScalar(a||1).multiplyScalar(Math.max(e,Math.min(t,a)))}floor(){return this.x=Math.floor(this.x),this.y=Math.floor(this.y),this}ceil(){return this.x=Math.ceil(this.x),this.y=Math.ceil(this.y),this}round(){return this.x=Math.round(this.x),this.y=Math.round(this.y),this}roundToZero(){return this.x=Math.trunc(this.x),this.y=Math.trunc(this.y),this}negate(){return this.x=-this.x,this.y=-this.y,this}dot(e){return this.x*e.x+this.y*e.y}cross(e){return this.x*e.y-this.y*e.x}lengthSq(){return this.x*this.x+this.y*this.y}length(){return Math.sqrt(this.x*this.x+this.y*this.y)}manhattanLength(){return Math.abs(this.x)+Math.abs(this.y)}normalize(){return this.divideScalar(this.length()||1)}angle(){return Math.atan2(-this.y,-this.x)+Math.PI}angleTo(e){const t=Math.sqrt(this.lengthSq()*e.lengthSq());if(t===0)return Math.PI/2;const a=this.dot(e)/t;return Math.acos(Mt(a,-1,1))}distanceTo(e){return Math.sqrt(this.distanceToSquared(e))}distanceToSquared(e){const t=this.x-e.x,a=this.y-e.y;return t*t+a*a}manhattanDistanceTo(e){return Math.abs(this.x-e.x)+Math.abs(this.y-e.y)}setLength(e){return this.normalize().multiplyScalar(e)}lerp(e,t){return this.x+=(e.x-this.x)*t,this.y+=(e.y-this.y)*t,this}lerpVectors(e,t,a){return this.x=e.x+(t.x-e.x)*a,this.y=e.y+(t.y-e.y)*a,this}equals(e){return e.x===this.x&&e.y===this.y}fromArray(e,t=0){return this.x=e[t],this.y=e[t+1],this}toArray(e=[],t=0){return e[t]=this.x,e[t+1]=this.y,e}fromBufferAttribute(e,t){return this.x=e.getX(t),this.y=e.getY(t),this}rotateAround(e,t){const a=Math.cos(t),i=Math.sin(t),r=this.x-e.x,s=this.y-e.y;return this.x=r*a-s*i+e.x,this.y=r*i+s*a+e.y,this}random(){return this.x=Math.random(),this.y=Math.random(),this}*[Symbol.iterator](){yield this.x,yield this.y}}class Pe{constructor(e,t,a,i,r,s,o,c,l){Pe.prototype.isMatrix3=!0,this.elements=[1,0,0,0,1,0,0,0,1],e!==void 0&&this.set(e,t,a,i,r,s,o,c,l)}set(e,t,a,i,r,s,o,c,l){const h=this.elements;return h[0]=e,h[1]=i,h[2]=o,h[3]=t,h[4]=r,h[5]=c,h[6]=a,h[7]=s,h[8]=l,this}identity(){return this.set(1,0,0,0,1,0,0,0,1),this}copy(e){const t=this.elements,a=e.elements;return t[0]=a[0],t[1]=a[1],t[2]=a[2],t[3]=a[3],t[4]=a[4],t[5]=a[5],t[6]=a[6],t[7]=a[7],t[8]=a[8],this}extractBasis(e,t,a){return e.setFromMatrix3Column(this,0),t.setFromMatrix3Column(this,1),a.setFromMatrix3Column(this,2),this}setFromMatrix4(e){const t=e.elements;return this.set(t[0],t[4],t[8],t[1],t[5],t[9],t[2],t[6],t[10]),this}multiply(e){return this.multiplyMatrices(this,e)}premultiply(e){return this.multiplyMatrices(e,this)}multiplyMatrices(e,t){const a=e.elements,i=t.elements,r=this.elements,s=a[0],o=a[3],c=a[6],l=a[1],h=a[4],d=a[7],f=a[2],b=a[5],p=a[8],g=i[0],m=i[3],u=i[6],y=i[1],x=i[4],v=i[7],E=i[2],_=i[5],A=i[8];return r[0]=s*g+o*y+c*E,r[3]=s*m+o*x+c*_,r[6]=s*u+o*v+c*A,r[1]=l*g+h*y+d*E,r[4]=l*m+h*x+d*_,r[7]=l*u+h*v+d*A,r[2]=f*g+b*y+p*E,r[5]=f*m+b*x+p*_,r[8]=f*u+b*v+p*A,this}multiplyScalar(e){const t=this.elements;return t[0]*=e,t[3]*=e,t[6]*=e,t[1]*=e,t[4]*=e,t[7]*=e,t[2]*=e,t[5]*=e,t[8]*=e,this}determinant(){const e=this.elements,t=e[0],a=e[1],i=e[2],r=e[3],s=e[4],o=e[5],c=e[6],l=e[7],h=e[8];return t*s*h-t*o*l-a*r*h+a*o*c+i*r*l-i*s*c}invert(){const e=this.elements,t=e[0],a=e[1],i=e[2],r=e[3],s=e[4],o=e[5],c=e[6],l=e[7],h=e[8],d=h*s-o*l,f=o*c-h*r,b=l*r-s*c,p=t*d+a*f+i*b;if(p===0)return this.set(0,0,0,0,0,0,0,0,0);const g=1/p;return e[0]=d*g,e[1]=(i*l-h*a)*g,e[2]=(o*a-i*s)*g,e[3]=f*g,e[4]=(h*t-i*c)*g,e[5]=(i*r-o*t)*g,e[6]=b*g,e[7]=(a*c-l*t)*g,e[8]=(s*t-a*r)*g,this}transpose(){let e;const t=this.elements;return e=t[1],t[1]=t[3],t[3]=e,e=t[2],t[2]=t[6],t[6]=e,e=t[5],t[5]=t[7],t[7]=e,this}getNormalMatrix(e){return this.setFromMatrix4(e).invert().transpose()}transposeIntoArray(e){const t=this.elements;return e[0]=t[0],e[1]=t[3],e[2]=t[6],e[3]=t[1],e[4]=t[4],e[5]=t[7],e[6]=t[2],e[7]=t[5],e[8]=t[8],this}setUvTransform(e,t,a,i,r,s,o){const c=Math.cos(r),l=Math.sin(r);return this.set(a*c,a*l,-a*(c*s+l*o)+s+e,-i*l,i*c,-i*(-l*s+c*o)+o+t,0,0,1),this}scale(e,t){return this.premultiply(Or.makeScale(e,t)),this}rotate(e){return this.premultiply(Or.makeRotation(-e)),this}translate(e,t){return this.premultiply(Or.makeTranslation(e,t)),this}makeTranslation(e,t){return e.isVector2?this.set(1,0,e.x,0,1,e.y,0,0,1):this.set(1,0,e,0,1,t,0,0,1),this}makeRotation(e){const t=Math.cos(e),a=Math.sin(e);return this.set(t,-a,0,a,t,0,0,0,1),this}makeScale(e,t){return this.set(e,0,0,0,t,0,0,0,1),this}equals(e){const t=this.elements,a=e.elements;for(let i=0;i<9;i++)if(t[i]!==a[i])return!1;return!0}fromArray(e,t=0){for(let a=0;a<9;a++)this.elements[a]=e[a+t];return this}toArray(e=[],t=0){const a=this.elements;return e[t]=a[0],e[t+1]=a[1],e[t+2]=a[2],e[t+3]=a[3],e[t+4]=a[4],e[t+5]=a[5],e[t+6]=a[6],e[t+7]=a[7],e[t+8]=a[8],e}clone(){return new this.constructor().fromArray(this.elements)}}const Or=new Pe;function Jl(n){for(let e=n.length-1;e>=0;--e)if(n[e]>=65535)return!0;return!1}function yr(n){return document.createElementNS("http://www.w3.org/1999/xhtml",n)}function fb(){const n=yr("canvas");return n.style.display="block",n}const kc={};function hi(n){n in kc||(kc[n]=!0,console.warn(n))}function ub(n,e,t){return new Promise(function(a,i){function r(){switch(n.clientWaitSync(e,n.SYNC_FLUSH_COMMANDS_BIT,0)){case n.WAIT_FAILED:i();break;case n.TIMEOUT_EXPIRED:setTimeout(r,t);break;default:a()}}setTimeout(r,t)})}function bb(n){const e=n.elements;e[2]=.5*e[2]+.5*e[3],e[6]=.5*e[6]+.5*e[7],e[10]=.5*e[10]+.5*e[11],e[14]=.5*e[14]+.5*e[15]}function mb(n){const e=n.elements;e[11]===-1?(e[10]=-e[10]-1,e[14]=-e[14]):(e[10]=-e[10],e[14]=-e[14]+1)}const qe={enabled:!0,workingColorSpace:Hn,spaces:{},convert:function(n,e,t){return this.enabled===!1||e===t||!e||!t||(this.spaces[e].transfer===et&&(n.r=ya(n.r),n.g=ya(n.g),n.b=ya(n.b)),this.spaces[e].primaries!==this.spaces[t].primaries&&(n.applyMatrix3(this.spaces[e].toXYZ),n.applyMatrix3(this.spaces[t].fromXYZ)),this.spaces[t].transfer===et&&(n.r=Nn(n.r),n.g=Nn(n.g),n.b=Nn(n.b))),n},fromWorkingColorSpace:function(n,e){return this.convert(n,this.workingColorSpace,e)},toWorkingColorSpace:function(n,e){return this.convert(n,e,this.workingColorSpace)},getPrimaries:function(n){return this.spaces[n].primaries},getTransfer:function(n){return n===ga?Rr:this.spaces[n].transfer},getLuminanceCoefficients:function(n,e=this.workingColorSpace){return n.fromArray(this.spaces[e].luminanceCoefficients)},define:function(n){Object.assign(this.spaces,n)},_getMatrix:function(n,e,t){return n.copy(this.spaces[e].toXYZ).multiply(this.spaces[t].fromXYZ)},_getDrawingBufferColorSpace:function(n){return this.spaces[n].outputColorSpaceConfig.drawingBufferColorSpace},_getUnpackColorSpace:function(n=this.workingColorSpace){return this.spaces[n].workingColorSpaceConfig.unpackColorSpace}};function ya(n){return n<.04045?n*.0773993808:Math.pow(n*.9478672986+.0521327014,2.4)}function Nn(n){return n<.0031308?n*12.92:1.055*Math.pow(n,.41666)-.055}const Rc=[.64,.33,.3,.6,.15,.06],Cc=[.2126,.7152,.0722],Ic=[.3127,.329],Pc=new Pe().set(.4123908,.3575843,.1804808,.212639,.7151687,.0721923,.0193308,.1191948,.9505322),Dc=new Pe().set(3.2409699,-1.5373832,-.4986108,-.9692436,1.8759675,.0415551,.0556301,-.203977,1.0569715);qe.define({[Hn]:{primaries:Rc,whitePoint:Ic,transfer:Rr,toXYZ:Pc,fromXYZ:Dc,luminanceCoefficients:Cc,workingColorSpaceConfig:{unpackColorSpace:kt},outputColorSpaceConfig:{drawingBufferColorSpace:kt}},[kt]:{primaries:Rc,whitePoint:Ic,transfer:et,toXYZ:Pc,fromXYZ:Dc,luminanceCoefficients:Cc,outputColorSpaceConfig:{drawingBufferColorSpace:kt}}});let bn;class pb{static getDataURL(e){if(/^data:/i.test(e.src)||typeof HTMLCanvasElement>"u")return e.src;let t;if(e instanceof HTMLCanvasElement)t=e;else{bn===void 0&&(bn=yr("canvas")),bn.width=e.width,bn.height=e.height;const a=bn.getContext("2d");e instanceof ImageData?a.putImageData(e,0,0):a.drawImage(e,0,0,e.width,e.height),t=bn}return t.width>2048||t.height>2048?(console.warn("THREE.ImageUtils.getDataURL: Image converted to jpg for performance reasons",e),t.toDataURL("image/jpeg",.6)):t.toDataURL("image/png")}static sRGBToLinear(e){if(typeof HTMLImageElement<"u"&&e instanceof HTMLImageElement||typeof HTMLCanvasElement<"u"&&e instanceof HTMLCanvasElement||typeof ImageBitmap<"u"&&e instanceof ImageBitmap){const t=yr("canvas");t.width=e.width,t.height=e.height;const a=t.getContext("2d");a.drawImage(e,0,0,e.width,e.height);const i=a.getImageData(0,0,e.width,e.height),r=i.data;for(let s=0;s<r.length;s++)r[s]=ya(r[s]/255)*255;return a.putImageData(i,0,0),t}else if(e.data){const t=e.data.slice(0);for(let a=0;a<t.length;a++)t instanceof Uint8Array||t instanceof Uint8ClampedArray?t[a]=Math.floor(ya(t[a]/255)*255):t[a]=ya(t[a]);return{data:t,width:e.width,height:e.height}}else return console.warn("THREE.ImageUtils.sRGBToLinear(): Unsupported image type. No color space conversion applied."),e}}let gb=0;class Yl{constructor(e=null){this.isSource=!0,Object.defineProperty(this,"id",{value:gb++}),this.uuid=oa(),this.data=e,this.dataReady=!0,this.version=0}set needsUpdate(e){e===!0&&this.version++}toJSON(e){const t=e===void 0||typeof e=="string";if(!t&&e.images[this.uuid]!==void 0)return e.images[this.uuid];const a={uuid:this.uuid,url:""},i=this.data;if(i!==null){let r;if(Array.isArray(i)){r=[];for(let s=0,o=i.length;s<o;s++)i[s].isDataTexture?r.push(zr(i[s].image)):r.push(zr(i[s]))}else r=zr(i);a.url=r}return t||(e.images[this.uuid]=a),a}}function zr(n){return typeof HTMLImageElement<"u"&&n instanceof HTMLImageElement||typeof HTMLCanvasElement<"u"&&n instanceof HTMLCanvasElement||typeof ImageBitmap<"u"&&n instanceof ImageBitmap?pb.getDataURL(n):n.data?{data:Array.from(n.data),width:n.width,height:n.height,type:n.data.constructor.name}:(console.warn("THREE.Texture: Unable to serialize Texture."),{})}let vb=0;class _t extends hn{constructor(e=_t.DEFAULT_IMAGE,t=_t.DEFAULT_MAPPING,a=za,i=za,r=na,s=Ba,o=Rt,c=_a,l=_t.DEFAULT_ANISOTROPY,h=ga){super(),this.isTexture=!0,Object.defineProperty(this,"id",{value:vb++}),this.uuid=oa(),this.name="",this.source=new Yl(e),this.mipmaps=[],this.mapping=t,this.channel=0,this.wrapS=a,this.wrapT=i,this.magFilter=r,this.minFilter=s,this.anisotropy=l,this.format=o,this.internalFormat=null,this.type=c,this.offset=new De(0,0),this.repeat=new De(1,1),this.center=new De(0,0),this.rotation=0,this.matrixAutoUpdate=!0,this.matrix=new Pe,this.generateMipmaps=!0,this.premultiplyAlpha=!1,this.flipY=!0,this.unpackAlignment=4,this.colorSpace=h,this.userData={},this.version=0,this.onUpdate=null,this.isRenderTargetTexture=!1,this.pmremVersion=0}get image(){return this.source.data}set image(e=null){this.source.data=e}updateMatrix(){this.matrix.setUvTransform(this.offset.x,this.offset.y,this.repeat.x,this.repeat.y,this.rotation,this.center.x,this.center.y)}clone(){return new this.constructor().copy(this)}copy(e){return this.name=e.name,this.source=e.source,this.mipmaps=e.mipmaps.slice(0),this.mapping=e.mapping,this.channel=e.channel,this.wrapS=e.wrapS,this.wrapT=e.wrapT,this.magFilter=e.magFilter,this.minFilter=e.minFilter,this.anisotropy=e.anisotropy,this.format=e.format,this.internalFormat=e.internalFormat,this.type=e.type,this.offset.copy(e.offset),this.repeat.copy(e.repeat),this.center.copy(e.center),this.rotation=e.rotation,this.matrixAutoUpdate=e.matrixAutoUpdate,this.matrix.copy(e.matrix),this.generateMipmaps=e.generateMipmaps,this.premultiplyAlpha=e.premultiplyAlpha,this.flipY=e.flipY,this.unpackAlignment=e.unpackAlignment,this.colorSpace=e.colorSpace,this.userData=JSON.parse(JSON.stringify(e.userData)),this.needsUpdate=!0,this}toJSON(e){const t=e===void 0||typeof e=="string";if(!t&&e.textures[this.uuid]!==void 0)return e.textures[this.uuid];const a={metadata:{version:4.6,type:"Texture",generator:"Texture.toJSON"},uuid:this.uuid,name:this.name,image:this.source.toJSON(e).uuid,mapping:this.mapping,channel:this.channel,repeat:[this.repeat.x,this.repeat.y],offset:[this.offset.x,this.offset.y],center:[this.center.x,this.center.y],rotation:this.rotation,wrap:[this.wrapS,this.wrapT],format:this.format,internalFormat:this.internalFormat,type:this.type,colorSpace:this.colorSpace,minFilter:this.minFilter,magFilter:this.magFilter,anisotropy:this.anisotropy,flipY:this.flipY,generateMipmaps:this.generateMipmaps,premultiplyAlpha:this.premultiplyAlpha,unpackAlignment:this.unpackAlignment};return Object.keys(this.userData).length>0&&(a.userData=this.userData),t||(e.textures[this.uuid]=a),a}dispose(){this.dispatchEvent({type:"dispose"})}transformUv(e){if(this.mapping!==Nl)return e;if(e.applyMatrix3(this.matrix),e.x<0||e.x>1)switch(this.wrapS){case pr:e.x=e.x-Math.floor(e.x);break;case za:e.x=e.x<0?0:1;break;case gr:Math.abs(Math.floor(e.x)%2)===1?e.x=Math.ceil(e.x)-e.x:e.x=e.x-Math.floor(e.x);break}if(e.y<0||e.y>1)switch(this.wrapT){case pr:e.y=e.y-Math.floor(e.y);break;case za:e.y=e.y<0?0:1;break;case gr:Math.abs(Math.floor(e.y)%2)===1?e.y=Math.ceil(e.y)-e.y:e.y=e.y-Math.floor(e.y);break}return this.flipY&&(e.y=1-e.y),e}set needsUpdate(e){e===!0&&(this.version++,this.source.needsUpdate=!0)}set needsPMREMUpdate(e){e===!0&&this.pmremVersion++}}_t.DEFAULT_IMAGE=null;_t.DEFAULT_MAPPING=Nl;_t.DEFAULT_ANISOTROPY=1;class ot{constructor(e=0,t=0,a=0,i=1){ot.prototype.isVector4=!0,this.x=e,this.y=t,this.z=a,this.w=i}get width(){return this.z}set width(e){this.z=e}get height(){return this.w}set height(e){this.w=e}set(e,t,a,i){return this.x=e,this.y=t,this.z=a,this.w=i,this}setScalar(e){return this.x=e,this.y=e,this.z=e,this.w=e,this}setX(e){return this.x=e,this}setY(e){return this.y=e,this}setZ(e){return this.z=e,this}setW(e){return this.w=e,this}setComponent(e,t){switch(e){case 0:this.x=t;break;case 1:this.y=t;break;case 2:this.z=t;break;case 3:this.w=t;break;default:throw new Error("index is out of range: "+e)}return this}getComponent(e){switch(e){case 0:return this.x;case 1:return this.y;case 2:return this.z;case 3:return this.w;default:throw new Error("index is out of range: "+e)}}clone(){return new this.constructor(this.x,this.y,this.z,this.w)}copy(e){return this.x=e.x,this.y=e.y,this.z=e.z,this.w=e.w!==void 0?e.w:1,this}add(e){return this.x+=e.x,this.y+=e.y,this.z+=e.z,this.w+=e.w,this}addScalar(e){return this.x+=e,this.y+=e,this.z+=e,this.w+=e,this}addVectors(e,t){return this.x=e.x+t.x,this.y=e.y+t.y,this.z=e.z+t.z,this.w=e.w+t.w,this}addScaledVector(e,t){return this.x+=e.x*t,this.y+=e.y*t,this.z+=e.z*t,this.w+=e.w*t,this}sub(e){return this.x-=e.x,this.y-=e.y,this.z-=e.z,this.w-=e.w,this}subScalar(e){return this.x-=e,this.y-=e,this.z-=e,this.w-=e,this}subVectors(e,t){return this.x=e.x-t.x,this.y=e.y-t.y,this.z=e.z-t.z,this.w=e.w-t.w,this}multiply(e){return this.x*=e.x,this.y*=e.y,this.z*=e.z,this.w*=e.w,this}multiplyScalar(e){return this.x*=e,this.y*=e,this.z*=e,this.w*=e,this}applyMatrix4(e){const t=this.x,a=this.y,i=this.z,r=this.w,s=e.elements;return this.x=s[0]*t+s[4]*a+s[8]*i+s[12]*r,this.y=s[1]*t+s[5]*a+s[9]*i+s[13]*r,this.z=s[2]*t+s[6]*a+s[10]*i+s[14]*r,this.w=s[3]*t+s[7]*a+s[11]*i+s[15]*r,this}divide(e){return this.x/=e.x,this.y/=e.y,this.z/=e.z,this.w/=e.w,this}divideScalar(e){return this.multiplyScalar(1/e)}setAxisAngleFromQuaternion(e){this.w=2*Math.acos(e.w);const t=Math.sqrt(1-e.w*e.w);return t<1e-4?(this.x=1,this.y=0,this.z=0):(this.x=e.x/t,this.y=e.y/t,this.z=e.z/t),this}setAxisAngleFromRotationMatrix(e){let t,a,i,r;const c=e.elements,l=c[0],h=c[4],d=c[8],f=c[1],b=c[5],p=c[9],g=c[2],m=c[6],u=c[10];if(Math.abs(h-f)<.01&&Math.abs(d-g)<.01&&Math.abs(p-m)<.01){if(Math.abs(h+f)<.1&&Math.abs(d+g)<.1&&Math.abs(p+m)<.1&&Math.abs(l+b+u-3)<.1)return this.set(1,0,0,0),this;t=Math.PI;const x=(l+1)/2,v=(b+1)/2,E=(u+1)/2,_=(h+f)/4,A=(d+g)/4,k=(p+m)/4;return x>v&&x>E?x<.01?(a=0,i=.707106781,r=.707106781):(a=Math.sqrt(x),i=_/a,r=A/a):v>E?v<.01?(a=.707106781,i=0,r=.707106781):(i=Math.sqrt(v),a=_/i,r=k/i):E<.01?(a=.707106781,i=.707106781,r=0):(r=Math.sqrt(E),a=A/r,i=k/r),this.set(a,i,r,t),this}let y=Math.sqrt((m-p)*(m-p)+(d-g)*(d-g)+(f-h)*(f-h));return Math.abs(y)<.001&&(y=1),this.x=(m-p)/y,this.y=(d-g)/y,this.z=(f-h)/y,this.w=Math.acos((l+b+u-1)/2),this}setFromMatrixPosition(e){const t=e.elements;return this.x=t[12],this.y=t[13],this.z=t[14],this.w=t[15],this}min(e){return this.x=Math.min(this.x,e.x),this.y=Math.min(this.y,e.y),this.z=Math.min(this.z,e.z),this.w=Math.min(this.w,e.w),this}max(e){return this.x=Math.max(this.x,e.x),this.y=Math.max(this.y,e.y),this.z=Math.max(this.z,e.z),this.w=Math.max(this.w,e.w),this}clamp(e,t){return this.x=Math.max(e.x,Math.min(t.x,this.x)),this.y=Math.max(e.y,Math.min(t.y,this.y)),this.z=Math.max(e.z,Math.min(t.z,this.z)),this.w=Math.max(e.w,Math.min(t.w,this.w)),this}clampScalar(e,t){return this.x=Math.max(e,Math.min(t,this.x)),this.y=Math.max(e,Math.min(t,this.y)),this.z=Math.max(e,Math.min(t,this.z)),this.w=Math.max(e,Math.min(t,this.w)),this}clampLength(e,t){const a=this.length();return this.divideScalar(a||1).multiplyScalar(Math.max(e,Math.min(t,a)))}floor(){return this.x=Math.floor(this.x),this.y=Math.floor(this.y),this.z=Math.floor(this.z),this.w=Math.floor(this.w),this}ceil(){return this.x=Math.ceil(this.x),this.y=Math.ceil(this.y),this.z=Math.ceil(this.z),this.w=Math.ceil(this.w),this}round(){return this.x=Math.round(this.x),this.y=Math.round(this.y),this.z=Math.round(this.z),this.w=Math.round(this.w),this}roundToZero(){return this.x=Math.trunc(this.x),this.y=Math.trunc(this.y),this.z=Math.trunc(this.z),this.w=Math.trunc(this.w),this}negate(){return this.x=-this.x,this.y=-this.y,this.z=-this.z,this.w=-this.w,this}dot(e){return this.x*e.x+this.y*e.y+this.z*e.z+this.w*e.w}lengthSq(){return this.x*this.x+this.y*this.y+this.z*this.z+this.w*this.w}length(){return Math.sqrt(this.x*this.x+this.y*this.y+this.z*this.z+this.w*this.w)}manhattanLength(){return Math.abs(this.x)+Math.abs(this.y)+Math.abs(this.z)+Math.abs(this.w)}normalize(){return this.divideScalar(this.length()||1)}setLength(e){return this.normalize().multiplyScalar(e)}lerp(e,t){return this.x+=(e.x-this.x)*t,this.y+=(e.y-this.y)*t,this.z+=(e.z-this.z)*t,this.w+=(e.w-this.w)*t,this}lerpVectors(e,t,a){return this.x=e.x+(t.x-e.x)*a,this.y=e.y+(t.y-e.y)*a,this.z=e.z+(t.z-e.z)*a,this.w=e.w+(t.w-e.w)*a,this}equals(e){return e.x===this.x&&e.y===this.y&&e.z===this.z&&e.w===this.w}fromArray(e,t=0){return this.x=e[t],this.y=e[t+1],this.z=e[t+2],this.w=e[t+3],this}toArray(e=[],t=0){return e[t]=this.x,e[t+1]=this.y,e[t+2]=this.z,e[t+3]=this.w,e}fromBufferAttribute(e,t){return this.x=e.getX(t),this.y=e.getY(t),this.z=e.getZ(t),this.w=e.getW(t),this}random(){return this.x=Math.random(),this.y=Math.random(),this.z=Math.random(),this.w=Math.random(),this}*[Symbol.iterator](){yield this.x,yield this.y,yield this.z,yield this.w}}class yb extends hn{constructor(e=1,t=1,a={}){super(),this.isRenderTarget=!0,this.width=e,this.height=t,this.depth=1,this.scissor=new ot(0,0,e,t),this.scissorTest=!1,this.viewport=new ot(0,0,e,t);const i={width:e,height:t,depth:1};a=Object.assign({generateMipmaps:!1,internalFormat:null,minFilter:na,depthBuffer:!0,stencilBuffer:!1,resolveDepthBuffer:!0,resolveStencilBuffer:!0,depthTexture:null,samples:0,count:1},a);const r=new _t(i,a.mapping,a.wrapS,a.wrapT,a.magFilter,a.minFilter,a.format,a.type,a.anisotropy,a.colorSpace);r.flipY=!1,r.generateMipmaps=a.generateMipmaps,r.internalFormat=a.internalFormat,this.textures=[];const s=a.count;for(let o=0;o<s;o++)this.textures[o]=r.clone(),this.textures[o].isRenderTargetTexture=!0;this.depthBuffer=a.depthBuffer,this.stencilBuffer=a.stencilBuffer,this.resolveDepthBuffer=a.resolveDepthBuffer,this.resolveStencilBuffer=a.resolveStencilBuffer,this.depthTexture=a.depthTexture,this.samples=a.samples}get texture(){return this.textures[0]}set texture(e){this.textures[0]=e}setSize(e,t,a=1){if(this.width!==e||this.height!==t||this.depth!==a){this.width=e,this.height=t,this.depth=a;for(let i=0,r=this.textures.length;i<r;i++)this.textures[i].image.width=e,this.textures[i].image.height=t,this.textures[i].image.depth=a;this.dispose()}this.viewport.set(0,0,e,t),this.scissor.set(0,0,e,t)}clone(){return new this.constructor().copy(this)}copy(e){this.width=e.width,this.height=e.height,this.depth=e.depth,this.scissor.copy(e.scissor),this.scissorTest=e.scissorTest,this.viewport.copy(e.viewport),this.textures.length=0;for(let a=0,i=e.textures.length;a<i;a++)this.textures[a]=e.textures[a].clone(),this.textures[a].isRenderTargetTexture=!0;const t=Object.assign({},e.texture.image);return this.texture.source=new Yl(t),this.depthBuffer=e.depthBuffer,this.stencilBuffer=e.stencilBuffer,this.resolveDepthBuffer=e.resolveDepthBuffer,this.resolveStencilBuffer=e.resolveStencilBuffer,e.depthTexture!==null&&(this.depthTexture=e.depthTexture.clone()),this.samples=e.samples,this}dispose(){this.dispatchEvent({type:"dispose"})}}class Sa extends yb{constructor(e=1,t=1,a={}){super(e,t,a),this.isWebGLRenderTarget=!0}}class Zl extends _t{constructor(e=null,t=1,a=1,i=1){super(null),this.isDataArrayTexture=!0,this.image={data:e,width:t,height:a,depth:i},this.magFilter=dt,this.minFilter=dt,this.wrapR=za,this.generateMipmaps=!1,this.flipY=!1,this.unpackAlignment=1,this.layerUpdates=new Set}addLayerUpdate(e){this.layerUpdates.add(e)}clearLayerUpdates(){this.layerUpdates.clear()}}class xb extends _t{constructor(e=null,t=1,a=1,i=1){super(null),this.isData3DTexture=!0,this.image={data:e,width:t,height:a,depth:i},this.magFilter=dt,this.minFilter=dt,this.wrapR=za,this.generateMipmaps=!1,this.flipY=!1,this.unpackAlignment=1}}class on{constructor(e=0,t=0,a=0,i=1){this.isQuaternion=!0,this._x=e,this._y=t,this._z=a,this._w=i}static slerpFlat(e,t,a,i,r,s,o){let c=a[i+0],l=a[i+1],h=a[i+2],d=a[i+3];const f=r[s+0],b=r[s+1],p=r[s+2],g=r[s+3];if(o===0){e[t+0]=c,e[t+1]=l,e[t+2]=h,e[t+3]=d;return}if(o===1){e[t+0]=f,e[t+1]=b,e[t+2]=p,e[t+3]=g;return}if(d!==g||c!==f||l!==b||h!==p){let m=1-o;const u=c*f+l*b+h*p+d*g,y=u>=0?1:-1,x=1-u*u;if(x>Number.EPSILON){const E=Math.sqrt(x),_=Math.atan2(E,u*y);m=Math.sin(m*_)/E,o=Math.sin(o*_)/E}const v=o*y;if(c=c*m+f*v,l=l*m+b*v,h=h*m+p*v,d=d*m+g*v,m===1-o){const E=1/Math.sqrt(c*c+l*l+h*h+d*d);c*=E,l*=E,h*=E,d*=E}}e[t]=c,e[t+1]=l,e[t+2]=h,e[t+3]=d}static multiplyQuaternionsFlat(e,t,a,i,r,s){const o=a[i],c=a[i+1],l=a[i+2],h=a[i+3],d=r[s],f=r[s+1],b=r[s+2],p=r[s+3];return e[t]=o*p+h*d+c*b-l*f,e[t+1]=c*p+h*f+l*d-o*b,e[t+2]=l*p+h*b+o*f-c*d,e[t+3]=h*p-o*d-c*f-l*b,e}get x(){return this._x}set x(e){this._x=e,this._onChangeCallback()}get y(){return this._y}set y(e){this._y=e,this._onChangeCallback()}get z(){return this._z}set z(e){this._z=e,this._onChangeCallback()}get w(){return this._w}set w(e){this._w=e,this._onChangeCallback()}set(e,t,a,i){return this._x=e,this._y=t,this._z=a,this._w=i,this._onChangeCallback(),this}clone(){return new this.constructor(this._x,this._y,this._z,this._w)}copy(e){return this._x=e.x,this._y=e.y,this._z=e.z,this._w=e.w,this._onChangeCallback(),this}setFromEuler(e,t=!0){const a=e._x,i=e._y,r=e._z,s=e._order,o=Math.cos,c=Math.sin,l=o(a/2),h=o(i/2),d=o(r/2),f=c(a/2),b=c(i/2),p=c(r/2);switch(s){case"XYZ":this._x=f*h*d+l*b*p,this._y=l*b*d-f*h*p,this._z=l*h*p+f*b*d,this._w=l*h*d-f*b*p;break;case"YXZ":this._x=f*h*d+l*b*p,this._y=l*b*d-f*h*p,this._z=l*h*p-f*b*d,this._w=l*h*d+f*b*p;break;case"ZXY":this._x=f*h*d-l*b*p,this._y=l*b*d+f*h*p,this._z=l*h*p+f*b*d,this._w=l*h*d-f*b*p;break;case"ZYX":this._x=f*h*d-l*b*p,this._y=l*b*d+f*h*p,this._z=l*h*p-f*b*d,this._w=l*h*d+f*b*p;break;case"YZX":this._x=f*h*d+l*b*p,this._y=l*b*d+f*h*p,this._z=l*h*p-f*b*d,this._w=l*h*d-f*b*p;break;case"XZY":this._x=f*h*d-l*b*p,this._y=l*b*d-f*h*p,this._z=l*h*p+f*b*d,this._w=l*h*d+f*b*p;break;default:console.warn("THREE.Quaternion: .setFromEuler() encountered an unknown order: "+s)}return t===!0&&this._onChangeCallback(),this}setFromAxisAngle(e,t){const a=t/2,i=Math.sin(a);return this._x=e.x*i,this._y=e.y*i,this._z=e.z*i,this._w=Math.cos(a),this._onChangeCallback(),this}setFromRotationMatrix(e){const t=e.elements,a=t[0],i=t[4],r=t[8],s=t[1],o=t[5],c=t[9],l=t[2],h=t[6],d=t[10],f=a+o+d;if(f>0){const b=.5/Math.sqrt(f+1);this._w=.25/b,this._x=(h-c)*b,this._y=(r-l)*b,this._z=(s-i)*b}else if(a>o&&a>d){const b=2*Math.sqrt(1+a-o-d);this._w=(h-c)/b,this._x=.25*b,this._y=(i+s)/b,this._z=(r+l)/b}else if(o>d){const b=2*Math.sqrt(1+o-a-d);this._w=(r-l)/b,this._x=(i+s)/b,this._y=.25*b,this._z=(c+h)/b}else{const b=2*Math.sqrt(1+d-a-o);this._w=(s-i)/b,this._x=(r+l)/b,this._y=(c+h)/b,this._z=.25*b}return this._onChangeCallback(),this}setFromUnitVectors(e,t){let a=e.dot(t)+1;return a<Number.EPSILON?(a=0,Math.abs(e.x)>Math.abs(e.z)?(this._x=-e.y,this._y=e.x,this._z=0,this._w=a):(this._x=0,this._y=-e.z,this._z=e.y,this._w=a)):(this._x=e.y*t.z-e.z*t.y,this._y=e.z*t.x-e.x*t.z,this._z=e.x*t.y-e.y*t.x,this._w=a),this.normalize()}angleTo(e){return 2*Math.acos(Math.abs(Mt(this.dot(e),-1,1)))}rotateTowards(e,t){const a=this.angleTo(e);if(a===0)return this;const i=Math.min(1,t/a);return this.slerp(e,i),this}identity(){return this.set(0,0,0,1)}invert(){return this.conjugate()}conjugate(){return this._x*=-1,this._y*=-1,this._z*=-1,this._onChangeCallback(),this}dot(e){return this._x*e._x+this._y*e._y+this._z*e._z+this._w*e._w}lengthSq(){return this._x*this._x+this._y*this._y+this._z*this._z+this._w*this._w}length(){return Math.sqrt(this._x*this._x+this._y*this._y+this._z*this._z+this._w*this._w)}normalize(){let e=this.length();return e===0?(this._x=0,this._y=0,this._z=0,this._w=1):(e=1/e,this._x=this._x*e,this._y=this._y*e,this._z=this._z*e,this._w=this._w*e),this._onChangeCallback(),this}multiply(e){return this.multiplyQuaternions(this,e)}premultiply(e){return this.multiplyQuaternions(e,this)}multiplyQuaternions(e,t){const a=e._x,i=e._y,r=e._z,s=e._w,o=t._x,c=t._y,l=t._z,h=t._w;return this._x=a*h+s*o+i*l-r*c,this._y=i*h+s*c+r*o-a*l,this._z=r*h+s*l+a*c-i*o,this._w=s*h-a*o-i*c-r*l,this._onChangeCallback(),this}slerp(e,t){if(t===0)return this;if(t===1)return this.copy(e);const a=this._x,i=this._y,r=this._z,s=this._w;let o=s*e._w+a*e._x+i*e._y+r*e._z;if(o<0?(this._w=-e._w,this._x=-e._x,this._y=-e._y,this._z=-e._z,o=-o):this.copy(e),o>=1)return this._w=s,this._x=a,this._y=i,this._z=r,this;const c=1-o*o;if(c<=Number.EPSILON){const b=1-t;return this._w=b*s+t*this._w,this._x=b*a+t*this._x,this._y=b*i+t*this._y,this._z=b*r+t*this._z,this.normalize(),this}const l=Math.sqrt(c),h=Math.atan2(l,o),d=Math.sin((1-t)*h)/l,f=Math.sin(t*h)/l;return this._w=s*d+this._w*f,this._x=a*d+this._x*f,this._y=i*d+this._y*f,this._z=r*d+this._z*f,this._onChangeCallback(),this}slerpQuaternions(e,t,a){return this.copy(e).slerp(t,a)}random(){const e=2*Math.PI*Math.random(),t=2*Math.PI*Math.random(),a=Math.random(),i=Math.sqrt(1-a),r=Math.sqrt(a);return this.set(i*Math.sin(e),i*Math.cos(e),r*Math.sin(t),r*Math.cos(t))}equals(e){return e._x===this._x&&e._y===this._y&&e._z===this._z&&e._w===this._w}fromArray(e,t=0){return this._x=e[t],this._y=e[t+1],this._z=e[t+2],this._w=e[t+3],this._onChangeCallback(),this}toArray(e=[],t=0){return e[t]=this._x,e[t+1]=this._y,e[t+2]=this._z,e[t+3]=this._w,e}fromBufferAttribute(e,t){return this._x=e.getX(t),this._y=e.getY(t),this._z=e.getZ(t),this._w=e.getW(t),this._onChangeCallback(),this}toJSON(){return this.toArray()}_onChange(e){return this._onChangeCallback=e,this}_onChangeCallback(){}*[Symbol.iterator](){yield this._x,yield this._y,yield this._z,yield this._w}}class O{constructor(e=0,t=0,a=0){O.prototype.isVector3=!0,this.x=e,this.y=t,this.z=a}set(e,t,a){return a===void 0&&(a=this.z),this.x=e,this.y=t,this.z=a,this}setScalar(e){return this.x=e,this.y=e,this.z=e,this}setX(e){return this.x=e,this}setY(e){return this.y=e,this}setZ(e){return this.z=e,this}setComponent(e,t){switch(e){case 0:this.x=t;break;case 1:this.y=t;break;case 2:this.z=t;break;default:throw new Error("index is out of range: "+e)}return this}getComponent(e){switch(e){case 0:return this.x;case 1:return this.y;case 2:return this.z;default:throw new Error("index is out of range: "+e)}}clone(){return new this.constructor(this.x,this.y,this.z)}copy(e){return this.x=e.x,this.y=e.y,this.z=e.z,this}add(e){return this.x+=e.x,this.y+=e.y,this.z+=e.z,this}addScalar(e){return this.x+=e,this.y+=e,this.z+=e,this}addVectors(e,t){return this.x=e.x+t.x,this.y=e.y+t.y,this.z=e.z+t.z,this}addScaledVector(e,t){return this.x+=e.x*t,this.y+=e.y*t,this.z+=e.z*t,this}sub(e){return this.x-=e.x,this.y-=e.y,this.z-=e.z,this}subScalar(e){return this.x-=e,this.y-=e,this.z-=e,this}subVectors(e,t){return this.x=e.x-t.x,this.y=e.y-t.y,this.z=e.z-t.z,this}multiply(e){return this.x*=e.x,this.y*=e.y,this.z*=e.z,this}multiplyScalar(e){return this.x*=e,this.y*=e,this.z*=e,this}multiplyVectors(e,t){return this.x=e.x*t.x,this.y=e.y*t.y,this.z=e.z*t.z,this}applyEuler(e){return this.applyQuaternion(Nc.setFromEuler(e))}applyAxisAngle(e,t){return this.applyQuaternion(Nc.setFromAxisAngle(e,t))}applyMatrix3(e){const t=this.x,a=this.y,i=this.z,r=e.elements;return this.x=r[0]*t+r[3]*a+r[6]*i,this.y=r[1]*t+r[4]*a+r[7]*i,this.z=r[2]*t+r[5]*a+r[8]*i,this}applyNormalMatrix(e){return this.applyMatrix3(e).normalize()}applyMatrix4(e){const t=this.x,a=this.y,i=this.z,r=e.elements,s=1/(r[3]*t+r[7]*a+r[11]*i+r[15]);return this.x=(r[0]*t+r[4]*a+r[8]*i+r[12])*s,this.y=(r[1]*t+r[5]*a+r[9]*i+r[13])*s,this.z=(r[2]*t+r[6]*a+r[10]*i+r[14])*s,this}applyQuaternion(e){const t=this.x,a=this.y,i=this.z,r=e.x,s=e.y,o=e.z,c=e.w,l=2*(s*i-o*a),h=2*(o*t-r*i),d=2*(r*a-s*t);return this.x=t+c*l+s*d-o*h,this.y=a+c*h+o*l-r*d,this.z=i+c*d+r*h-s*l,this}project(e){return this.applyMatrix4(e.matrixWorldInverse).applyMatrix4(e.projectionMatrix)}unproject(e){return this.applyMatrix4(e.projectionMatrixInverse).applyMatrix4(e.matrixWorld)}transformDirection(e){const t=this.x,a=this.y,i=this.z,r=e.elements;return this.x=r[0]*t+r[4]*a+r[8]*i,this.y=r[1]*t+r[5]*a+r[9]*i,this.z=r[2]*t+r[6]*a+r[10]*i,this.normalize()}divide(e){return this.x/=e.x,this.y/=e.y,this.z/=e.z,this}divideScalar(e){return this.multiplyScalar(1/e)}min(e){return this.x=Math.min(this.x,e.x),this.y=Math.min(this.y,e.y),this.z=Math.min(this.z,e.z),this}max(e){return this.x=Math.max(this.x,e.x),this.y=Math.max(this.y,e.y),this.z=Math.max(this.z,e.z),this}clamp(e,t){return this.x=Math.max(e.x,Math.min(t.x,this.x)),this.y=Math.max(e.y,Math.min(t.y,this.y)),this.z=Math.max(e.z,Math.min(t.z,this.z)),this}clampScalar(e,t){return this.x=Math.max(e,Math.min(t,this.x)),this.y=Math.max(e,Math.min(t,this.y)),this.z=Math.max(e,Math.min(t,this.z)),this}clampLength(e,t){const a=this.length();return this.divideScalar(a||1).multiplyScalar(Math.max(e,Math.min(t,a)))}floor(){return this.x=Math.floor(this.x),this.y=Math.floor(this.y),this.z=Math.floor(this.z),this}ceil(){return this.x=Math.ceil(this.x),this.y=Math.ceil(this.y),this.z=Math.ceil(this.z),this}round(){return this.x=Math.round(this.x),this.y=Math.round(this.y),this.z=Math.round(this.z),this}roundToZero(){return this.x=Math.trunc(this.x),this.y=Math.trunc(this.y),this.z=Math.trunc(this.z),this}negate(){return this.x=-this.x,this.y=-this.y,this.z=-this.z,this}dot(e){return this.x*e.x+this.y*e.y+this.z*e.z}lengthSq(){return this.x*this.x+this.y*this.y+this.z*this.z}length(){return Math.sqrt(this.x*this.x+this.y*this.y+this.z*this.z)}manhattanLength(){return Math.abs(this.x)+Math.abs(this.y)+Math.abs(this.z)}normalize(){return this.divideScalar(this.length()||1)}setLength(e){return this.normalize().multiplyScalar(e)}lerp(e,t){return this.x+=(e.x-this.x)*t,this.y+=(e.y-this.y)*t,this.z+=(e.z-this.z)*t,this}lerpVectors(e,t,a){return this.x=e.x+(t.x-e.x)*a,this.y=e.y+(t.y-e.y)*a,this.z=e.z+(t.z-e.z)*a,this}cross(e){return this.crossVectors(this,e)}crossVectors(e,t){const a=e.x,i=e.y,r=e.z,s=t.x,o=t.y,c=t.z;return this.x=i*c-r*o,this.y=r*s-a*c,this.z=a*o-i*s,this}projectOnVector(e){const t=e.lengthSq();if(t===0)return this.set(0,0,0);const a=e.dot(this)/t;return this.copy(e).multiplyScalar(a)}projectOnPlane(e){return Br.copy(this).projectOnVector(e),this.sub(Br)}reflect(e){return this.sub(Br.copy(e).multiplyScalar(2*this.dot(e)))}angleTo(e){const t=Math.sqrt(this.lengthSq()*e.lengthSq());if(t===0)return Math.PI/2;const a=this.dot(e)/t;return Math.acos(Mt(a,-1,1))}distanceTo(e){return Math.sqrt(this.distanceToSquared(e))}distanceToSquared(e){const t=this.x-e.x,a=this.y-e.y,i=this.z-e.z;return t*t+a*a+i*i}manhattanDistanceTo(e){return Math.abs(this.x-e.x)+Math.abs(this.y-e.y)+Math.abs(this.z-e.z)}setFromSpherical(e){return this.setFromSphericalCoords(e.radius,e.phi,e.theta)}setFromSphericalCoords(e,t,a){const i=Math.sin(t)*e;return this.x=i*Math.sin(a),this.y=Math.cos(t)*e,this.z=i*Math.cos(a),this}setFromCylindrical(e){return this.setFromCylindricalCoords(e.radius,e.theta,e.y)}setFromCylindricalCoords(e,t,a){return this.x=e*Math.sin(t),this.y=a,this.z=e*Math.cos(t),this}setFromMatrixPosition(e){const t=e.elements;return this.x=t[12],this.y=t[13],this.z=t[14],this}setFromMatrixScale(e){const t=this.setFromMatrixColumn(e,0).length(),a=this.setFromMatrixColumn(e,1).length(),i=this.setFromMatrixColumn(e,2).length();return this.x=t,this.y=a,this.z=i,this}setFromMatrixColumn(e,t){return this.fromArray(e.elements,t*4)}setFromMatrix3Column(e,t){return this.fromArray(e.elements,t*3)}setFromEuler(e){return this.x=e._x,this.y=e._y,this.z=e._z,this}setFromColor(e){return this.x=e.r,this.y=e.g,this.z=e.b,this}equals(e){return e.x===this.x&&e.y===this.y&&e.z===this.z}fromArray(e,t=0){return this.x=e[t],this.y=e[t+1],this.z=e[t+2],this}toArray(e=[],t=0){return e[t]=this.x,e[t+1]=this.y,e[t+2]=this.z,e}fromBufferAttribute(e,t){return this.x=e.getX(t),this.y=e.getY(t),this.z=e.getZ(t),this}random(){return this.x=Math.random(),this.y=Math.random(),this.z=Math.random(),this}randomDirection(){const e=Math.random()*Math.PI*2,t=Math.random()*2-1,a=Math.sqrt(1-t*t);return this.x=a*Math.cos(e),this.y=t,this.z=a*Math.sin(e),this}*[Symbol.iterator](){yield this.x,yield this.y,yield this.z}}const Br=new O,Nc=new on;class ln{constructor(e=new O(1/0,1/0,1/0),t=new O(-1/0,-1/0,-1/0)){this.isBox3=!0,this.min=e,this.max=t}set(e,t){return this.min.copy(e),this.max.copy(t),this}setFromArray(e){this.makeEmpty();for(let t=0,a=e.length;t<a;t+=3)this.expandByPoint(Qt.fromArray(e,t));return this}setFromBufferAttribute(e){this.makeEmpty();for(let t=0,a=e.count;t<a;t++)this.expandByPoint(Qt.fromBufferAttribute(e,t));return this}setFromPoints(e){this.makeEmpty();for(let t=0,a=e.length;t<a;t++)this.expandByPoint(e[t]);return this}setFromCenterAndSize(e,t){const a=Qt.copy(t).multiplyScalar(.5);return this.min.copy(e).sub(a),this.max.copy(e).add(a),this}setFromObject(e,t=!1){return this.makeEmpty(),this.expandByObject(e,t)}clone(){return new this.constructor().copy(this)}copy(e){return this.min.copy(e.min),this.max.copy(e.max),this}makeEmpty(){return this.min.x=this.min.y=this.min.z=1/0,this.max.x=this.max.y=this.max.z=-1/0,this}isEmpty(){return this.max.x<this.min.x||this.max.y<this.min.y||this.max.z<this.min.z}getCenter(e){return this.isEmpty()?e.set(0,0,0):e.addVectors(this.min,this.max).multiplyScalar(.5)}getSize(e){return this.isEmpty()?e.set(0,0,0):e.subVectors(this.max,this.min)}expandByPoint(e){return this.min.min(e),this.max.max(e),this}expandByVector(e){return this.min.sub(e),this.max.add(e),this}expandByScalar(e){return this.min.addScalar(-e),this.max.addScalar(e),this}expandByObject(e,t=!1){e.updateWorldMatrix(!1,!1);const a=e.geometry;if(a!==void 0){const r=a.getAttribute("position");if(t===!0&&r!==void 0&&e.isInstancedMesh!==!0)for(let s=0,o=r.count;s<o;s++)e.isMesh===!0?e.getVertexPosition(s,Qt):Qt.fromBufferAttribute(r,s),Qt.applyMatrix4(e.matrixWorld),this.expandByPoint(Qt);else e.boundingBox!==void 0?(e.boundingBox===null&&e.computeBoundingBox(),Ii.copy(e.boundingBox)):(a.boundingBox===null&&a.computeBoundingBox(),Ii.copy(a.boundingBox)),Ii.applyMatrix4(e.matrixWorld),this.union(Ii)}const i=e.children;for(let r=0,s=i.length;r<s;r++)this.expandByObject(i[r],t);return this}containsPoint(e){return e.x>=this.min.x&&e.x<=this.max.x&&e.y>=this.min.y&&e.y<=this.max.y&&e.z>=this.min.z&&e.z<=this.max.z}containsBox(e){return this.min.x<=e.min.x&&e.max.x<=this.max.x&&this.min.y<=e.min.y&&e.max.y<=this.max.y&&this.min.z<=e.min.z&&e.max.z<=this.max.z}getParameter(e,t){return t.set((e.x-this.min.x)/(this.max.x-this.min.x),(e.y-this.min.y)/(this.max.y-this.min.y),(e.z-this.min.z)/(this.max.z-this.min.z))}intersectsBox(e){return e.max.x>=this.min.x&&e.min.x<=this.max.x&&e.max.y>=this.min.y&&e.min.y<=this.max.y&&e.max.z>=this.min.z&&e.min.z<=this.max.z}intersectsSphere(e){return this.clampPoint(e.center,Qt),Qt.distanceToSquared(e.center)<=e.radius*e.radius}intersectsPlane(e){let t,a;return e.normal.x>0?(t=e.normal.x*this.min.x,a=e.normal.x*this.max.x):(t=e.normal.x*this.max.x,a=e.normal.x*this.min.x),e.normal.y>0?(t+=e.normal.y*this.min.y,a+=e.normal.y*this.max.y):(t+=e.normal.y*this.max.y,a+=e.normal.y*this.min.y),e.normal.z>0?(t+=e.normal.z*this.min.z,a+=e.normal.z*this.max.z):(t+=e.normal.z*this.max.z,a+=e.normal.z*this.min.z),t<=-e.constant&&a>=-e.constant}intersectsTriangle(e){if(this.isEmpty())return!1;this.getCenter(Zn),Pi.subVectors(this.max,Zn),mn.subVectors(e.a,Zn),pn.subVectors(e.b,Zn),gn.subVectors(e.c,Zn),Ia.subVectors(pn,mn),Pa.subVectors(gn,pn),Xa.subVectors(mn,gn);let t=[0,-Ia.z,Ia.y,0,-Pa.z,Pa.y,0,-Xa.z,Xa.y,Ia.z,0,-Ia.x,Pa.z,0,-Pa.x,Xa.z,0,-Xa.x,-Ia.y,Ia.x,0,-Pa.y,Pa.x,0,-Xa.y,Xa.x,0];return!Gr(t,mn,pn,gn,Pi)||(t=[1,0,0,0,1,0,0,0,1],!Gr(t,mn,pn,gn,Pi))?!1:(Di.crossVectors(Ia,Pa),t=[Di.x,Di.y,Di.z],Gr(t,mn,pn,gn,Pi))}clampPoint(e,t){return t.copy(e).clamp(this.min,this.max)}distanceToPoint(e){return this.clampPoint(e,Qt).distanceTo(e)}getBoundingSphere(e){return this.isEmpty()?e.makeEmpty():(this.getCenter(e.center),e.radius=this.getSize(Qt).length()*.5),e}intersect(e){return this.min.max(e.min),this.max.min(e.max),this.isEmpty()&&this.makeEmpty(),this}union(e){return this.min.min(e.min),this.max.max(e.max),this}applyMatrix4(e){return this.isEmpty()?this:(da[0].set(this.min.x,this.min.y,this.min.z).applyMatrix4(e),da[1].set(this.min.x,this.min.y,this.max.z).applyMatrix4(e),da[2].set(this.min.x,this.max.y,this.min.z).applyMatrix4(e),da[3].set(this.min.x,this.max.y,this.max.z).applyMatrix4(e),da[4].set(this.max.x,this.min.y,this.min.z).applyMatrix4(e),da[5].set(this.max.x,this.min.y,this.max.z).applyMatrix4(e),da[6].set(this.max.x,this.max.y,this.min.z).applyMatrix4(e),da[7].set(this.max.x,this.max.y,this.max.z).applyMatrix4(e),this.setFromPoints(da),this)}translate(e){return this.min.add(e),this.max.add(e),this}equals(e){return e.min.equals(this.min)&&e.max.equals(this.max)}}const da=[new O,new O,new O,new O,new O,new O,new O,new O],Qt=new O,Ii=new ln,mn=new O,pn=new O,gn=new O,Ia=new O,Pa=new O,Xa=new O,Zn=new O,Pi=new O,Di=new O,Ka=new O;function Gr(n,e,t,a,i){for(let r=0,s=n.length-3;r<=s;r+=3){Ka.fromArray(n,r);const o=i.x*Math.abs(Ka.x)+i.y*Math.abs(Ka.y)+i.z*Math.abs(Ka.z),c=e.dot(Ka),l=t.dot(Ka),h=a.dot(Ka);if(Math.max(-Math.max(c,l,h),Math.min(c,l,h))>o)return!1}return!0}const wb=new ln,Qn=new O,Hr=new O;class dn{constructor(e=new O,t=-1){this.isSphere=!0,this.center=e,this.radius=t}set(e,t){return this.center.copy(e),this.radius=t,this}setFromPoints(e,t){const a=this.center;t!==void 0?a.copy(t):wb.setFromPoints(e).getCenter(a);let i=0;for(let r=0,s=e.length;r<s;r++)i=Math.max(i,a.distanceToSquared(e[r]));return this.radius=Math.sqrt(i),this}copy(e){return this.center.copy(e.center),this.radius=e.radius,this}isEmpty(){return this.radius<0}makeEmpty(){return this.center.set(0,0,0),this.radius=-1,this}containsPoint(e){return e.distanceToSquared(this.center)<=this.radius*this.radius}distanceToPoint(e){return e.distanceTo(this.center)-this.radius}intersectsSphere(e){const t=this.radius+e.radius;return e.center.distanceToSquared(this.center)<=t*t}intersectsBox(e){return e.intersectsSphere(this)}intersectsPlane(e){return Math.abs(e.distanceToPoint(this.center))<=this.radius}clampPoint(e,t){const a=this.center.distanceToSquared(e);return t.copy(e),a>this.radius*this.radius&&(t.sub(this.center).normalize(),t.multiplyScalar(this.radius).add(this.center)),t}getBoundingBox(e){return this.isEmpty()?(e.makeEmpty(),e):(e.set(this.center,this.center),e.expandByScalar(this.radius),e)}applyMatrix4(e){return this.center.applyMatrix4(e),this.radius=this.radius*e.getMaxScaleOnAxis(),this}translate(e){return this.center.add(e),this}expandByPoint(e){if(this.isEmpty())return this.center.copy(e),this.radius=0,this;Qn.subVectors(e,this.center);const t=Qn.lengthSq();if(t>this.radius*this.radius){const a=Math.sqrt(t),i=(a-this.radius)*.5;this.center.addScaledVector(Qn,i/a),this.radius+=i}return this}union(e){return e.isEmpty()?this:this.isEmpty()?(this.copy(e),this):(this.center.equals(e.center)===!0?this.radius=Math.max(this.radius,e.radius):(Hr.subVectors(e.center,this.center).setLength(e.radius),this.expandByPoint(Qn.copy(e.center).add(Hr)),this.expandByPoint(Qn.copy(e.center).sub(Hr))),this)}equals(e){return e.center.equals(this.center)&&e.radius===this.radius}clone(){return new this.constructor().copy(this)}}const fa=new O,Vr=new O,Ni=new O,Da=new O,Wr=new O,Ui=new O,qr=new O;class Ai{constructor(e=new O,t=new O(0,0,-1)){this.origin=e,this.direction=t}set(e,t){return this.origin.copy(e),this.direction.copy(t),this}copy(e){return this.origin.copy(e.origin),this.direction.copy(e.direction),this}at(e,t){return t.copy(this.origin).addScaledVector(this.direction,e)}lookAt(e){return this.direction.copy(e).sub(this.origin).normalize(),this}recast(e){return this.origin.copy(this.at(e,fa)),this}closestPointToPoint(e,t){t.subVectors(e,this.origin);const a=t.dot(this.direction);return a<0?t.copy(this.origin):t.copy(this.origin).addScaledVector(this.direction,a)}distanceToPoint(e){return Math.sqrt(this.distanceSqToPoint(e))}distanceSqToPoint(e){const t=fa.subVectors(e,this.origin).dot(this.direction);return t<0?this.origin.distanceToSquared(e):(fa.copy(this.origin).addScaledVector(this.direction,t),fa.distanceToSquared(e))}distanceSqToSegment(e,t,a,i){Vr.copy(e).add(t).multiplyScalar(.5),Ni.copy(t).sub(e).normalize(),Da.copy(this.origin).sub(Vr);const r=e.distanceTo(t)*.5,s=-this.direction.dot(Ni),o=Da.dot(this.direction),c=-Da.dot(Ni),l=Da.lengthSq(),h=Math.abs(1-s*s);let d,f,b,p;if(h>0)if(d=s*c-o,f=s*o-c,p=r*h,d>=0)if(f>=-p)if(f<=p){const g=1/h;d*=g,f*=g,b=d*(d+s*f+2*o)+f*(s*d+f+2*c)+l}else f=r,d=Math.max(0,-(s*f+o)),b=-d*d+f*(f+2*c)+l;else f=-r,d=Math.max(0,-(s*f+o)),b=-d*d+f*(f+2*c)+l;else f<=-p?(d=Math.max(0,-(-s*r+o)),f=d>0?-r:Math.min(Math.max(-r,-c),r),b=-d*d+f*(f+2*c)+l):f<=p?(d=0,f=Math.min(Math.max(-r,-c),r),b=f*(f+2*c)+l):(d=Math.max(0,-(s*r+o)),f=d>0?r:Math.min(Math.max(-r,-c),r),b=-d*d+f*(f+2*c)+l);else f=s>0?-r:r,d=Math.max(0,-(s*f+o)),b=-d*d+f*(f+2*c)+l;return a&&a.copy(this.origin).addScaledVector(this.direction,d),i&&i.copy(Vr).addScaledVector(Ni,f),b}intersectSphere(e,t){fa.subVectors(e.center,this.origin);const a=fa.dot(this.direction),i=fa.dot(fa)-a*a,r=e.radius*e.radius;if(i>r)return null;const s=Math.sqrt(r-i),o=a-s,c=a+s;return c<0?null:o<0?this.at(c,t):this.at(o,t)}intersectsSphere(e){return this.distanceSqToPoint(e.center)<=e.radius*e.radius}distanceToPlane(e){const t=e.normal.dot(this.direction);if(t===0)return e.distanceToPoint(this.origin)===0?0:null;const a=-(this.origin.dot(e.normal)+e.constant)/t;return a>=0?a:null}intersectPlane(e,t){const a=this.distanceToPlane(e);return a===null?null:this.at(a,t)}intersectsPlane(e){const t=e.distanceToPoint(this.origin);return t===0||e.normal.dot(this.direction)*t<0}intersectBox(e,t){let a,i,r,s,o,c;const l=1/this.direction.x,h=1/this.direction.y,d=1/this.direction.z,f=this.origin;return l>=0?(a=(e.min.x-f.x)*l,i=(e.max.x-f.x)*l):(a=(e.max.x-f.x)*l,i=(e.min.x-f.x)*l),h>=0?(r=(e.min.y-f.y)*h,s=(e.max.y-f.y)*h):(r=(e.max.y-f.y)*h,s=(e.min.y-f.y)*h),a>s||r>i||((r>a||isNaN(a))&&(a=r),(s<i||isNaN(i))&&(i=s),d>=0?(o=(e.min.z-f.z)*d,c=(e.max.z-f.z)*d):(o=(e.max.z-f.z)*d,c=(e.min.z-f.z)*d),a>c||o>i)||((o>a||a!==a)&&(a=o),(c<i||i!==i)&&(i=c),i<0)?null:this.at(a>=0?a:i,t)}intersectsBox(e){return this.intersectBox(e,fa)!==null}intersectTriangle(e,t,a,i,r){Wr.subVectors(t,e),Ui.subVectors(a,e),qr.crossVectors(Wr,Ui);let s=this.direction.dot(qr),o;if(s>0){if(i)return null;o=1}else if(s<0)o=-1,s=-s;else return null;Da.subVectors(this.origin,e);const c=o*this.direction.dot(Ui.crossVectors(Da,Ui));if(c<0)return null;const l=o*this.direction.dot(Wr.cross(Da));if(l<0||c+l>s)return null;const h=-o*Da.dot(qr);return h<0?null:this.at(h/s,r)}applyMatrix4(e){return this.origin.applyMatrix4(e),this.direction.transformDirection(e),this}equals(e){return e.origin.equals(this.origin)&&e.direction.equals(this.direction)}clone(){return new this.constructor().copy(this)}}class ze{constructor(e,t,a,i,r,s,o,c,l,h,d,f,b,p,g,m){ze.prototype.isMatrix4=!0,this.elements=[1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1],e!==void 0&&this.set(e,t,a,i,r,s,o,c,l,h,d,f,b,p,g,m)}set(e,t,a,i,r,s,o,c,l,h,d,f,b,p,g,m){const u=this.elements;return u[0]=e,u[4]=t,u[8]=a,u[12]=i,u[1]=r,u[5]=s,u[9]=o,u[13]=c,u[2]=l,u[6]=h,u[10]=d,u[14]=f,u[3]=b,u[7]=p,u[11]=g,u[15]=m,this}identity(){return this.set(1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1),this}clone(){return new ze().fromArray(this.elements)}copy(e){const t=this.elements,a=e.elements;return t[0]=a[0],t[1]=a[1],t[2]=a[2],t[3]=a[3],t[4]=a[4],t[5]=a[5],t[6]=a[6],t[7]=a[7],t[8]=a[8],t[9]=a[9],t[10]=a[10],t[11]=a[11],t[12]=a[12],t[13]=a[13],t[14]=a[14],t[15]=a[15],this}copyPosition(e){const t=this.elements,a=e.elements;return t[12]=a[12],t[13]=a[13],t[14]=a[14],this}setFromMatrix3(e){const t=e.elements;return this.set(t[0],t[3],t[6],0,t[1],t[4],t[7],0,t[2],t[5],t[8],0,0,0,0,1),this}extractBasis(e,t,a){return e.setFromMatrixColumn(this,0),t.setFromMatrixColumn(this,1),a.setFromMatrixColumn(this,2),this}makeBasis(e,t,a){return this.set(e.x,t.x,a.x,0,e.y,t.y,a.y,0,e.z,t.z,a.z,0,0,0,0,1),this}extractRotation(e){const t=this.elements,a=e.elements,i=1/vn.setFromMatrixColumn(e,0).length(),r=1/vn.setFromMatrixColumn(e,1).length(),s=1/vn.setFromMatrixColumn(e,2).length();return t[0]=a[0]*i,t[1]=a[1]*i,t[2]=a[2]*i,t[3]=0,t[4]=a[4]*r,t[5]=a[5]*r,t[6]=a[6]*r,t[7]=0,t[8]=a[8]*s,t[9]=a[9]*s,t[10]=a[10]*s,t[11]=0,t[12]=0,t[13]=0,t[14]=0,t[15]=1,this}makeRotationFromEuler(e){const t=this.elements,a=e.x,i=e.y,r=e.z,s=Math.cos(a),o=Math.sin(a),c=Math.cos(i),l=Math.sin(i),h=Math.cos(r),d=Math.sin(r);if(e.order==="XYZ"){const f=s*h,b=s*d,p=o*h,g=o*d;t[0]=c*h,t[4]=-c*d,t[8]=l,t[1]=b+p*l,t[5]=f-g*l,t[9]=-o*c,t[2]=g-f*l,t[6]=p+b*l,t[10]=s*c}else if(e.order==="YXZ"){const f=c*h,b=c*d,p=l*h,g=l*d;t[0]=f+g*o,t[4]=p*o-b,t[8]=s*l,t[1]=s*d,t[5]=s*h,t[9]=-o,t[2]=b*o-p,t[6]=g+f*o,t[10]=s*c}else if(e.order==="ZXY"){const f=c*h,b=c*d,p=l*h,g=l*d;t[0]=f-g*o,t[4]=-s*d,t[8]=p+b*o,t[1]=b+p*o,t[5]=s*h,t[9]=g-f*o,t[2]=-s*l,t[6]=o,t[10]=s*c}else if(e.order==="ZYX"){const f=s*h,b=s*d,p=o*h,g=o*d;t[0]=c*h,t[4]=p*l-b,t[8]=f*l+g,t[1]=c*d,t[5]=g*l+f,t[9]=b*l-p,t[2]=-l,t[6]=o*c,t[10]=s*c}else if(e.order==="YZX"){const f=s*c,b=s*l,p=o*c,g=o*l;t[0]=c*h,t[4]=g-f*d,t[8]=p*d+b,t[1]=d,t[5]=s*h,t[9]=-o*h,t[2]=-l*h,t[6]=b*d+p,t[10]=f-g*d}else if(e.order==="XZY"){const f=s*c,b=s*l,p=o*c,g=o*l;t[0]=c*h,t[4]=-d,t[8]=l*h,t[1]=f*d+g,t[5]=s*h,t[9]=b*d-p,t[2]=p*d-b,t[6]=o*h,t[10]=g*d+f}return t[3]=0,t[7]=0,t[11]=0,t[12]=0,t[13]=0,t[14]=0,t[15]=1,this}makeRotationFromQuaternion(e){return this.compose(Mb,e,_b)}lookAt(e,t,a){const i=this.elements;return Lt.subVectors(e,t),Lt.lengthSq()===0&&(Lt.z=1),Lt.normalize(),Na.crossVectors(a,Lt),Na.lengthSq()===0&&(Math.abs(a.z)===1?Lt.x+=1e-4:Lt.z+=1e-4,Lt.normalize(),Na.crossVectors(a,Lt)),Na.normalize(),Fi.crossVectors(Lt,Na),i[0]=Na.x,i[4]=Fi.x,i[8]=Lt.x,i[1]=Na.y,i[5]=Fi.y,i[9]=Lt.y,i[2]=Na.z,i[6]=Fi.z,i[10]=Lt.z,this}multiply(e){return this.multiplyMatrices(this,e)}premultiply(e){return this.multiplyMatrices(e,this)}multiplyMatrices(e,t){const a=e.elements,i=t.elements,r=this.elements,s=a[0],o=a[4],c=a[8],l=a[12],h=a[1],d=a[5],f=a[9],b=a[13],p=a[2],g=a[6],m=a[10],u=a[14],y=a[3],x=a[7],v=a[11],E=a[15],_=i[0],A=i[4],k=i[8],w=i[12],M=i[1],R=i[5],U=i[9],P=i[13],D=i[2],V=i[6],B=i[10],G=i[14],z=i[3],Y=i[7],te=i[11],ie=i[15];return r[0]=s*_+o*M+c*D+l*z,r[4]=s*A+o*R+c*V+l*Y,r[8]=s*k+o*U+c*B+l*te,r[12]=s*w+o*P+c*G+l*ie,r[1]=h*_+d*M+f*D+b*z,r[5]=h*A+d*R+f*V+b*Y,r[9]=h*k+d*U+f*B+b*te,r[13]=h*w+d*P+f*G+b*ie,r[2]=p*_+g*M+m*D+u*z,r[6]=p*A+g*R+m*V+u*Y,r[10]=p*k+g*U+m*B+u*te,r[14]=p*w+g*P+m*G+u*ie,r[3]=y*_+x*M+v*D+E*z,r[7]=y*A+x*R+v*V+E*Y,r[11]=y*k+x*U+v*B+E*te,r[15]=y*w+x*P+v*G+E*ie,this}multiplyScalar(e){const t=this.elements;return t[0]*=e,t[4]*=e,t[8]*=e,t[12]*=e,t[1]*=e,t[5]*=e,t[9]*=e,t[13]*=e,t[2]*=e,t[6]*=e,t[10]*=e,t[14]*=e,t[3]*=e,t[7]*=e,t[11]*=e,t[15]*=e,this}determinant(){const e=this.elements,t=e[0],a=e[4],i=e[8],r=e[12],s=e[1],o=e[5],c=e[9],l=e[13],h=e[2],d=e[6],f=e[10],b=e[14],p=e[3],g=e[7],m=e[11],u=e[15];return p*(+r*c*d-i*l*d-r*o*f+a*l*f+i*o*b-a*c*b)+g*(+t*c*b-t*l*f+r*s*f-i*s*b+i*l*h-r*c*h)+m*(+t*l*d-t*o*b-r*s*d+a*s*b+r*o*h-a*l*h)+u*(-i*o*h-t*c*d+t*o*f+i*s*d-a*s*f+a*c*h)}transpose(){const e=this.elements;let t;return t=e[1],e[1]=e[4],e[4]=t,t=e[2],e[2]=e[8],e[8]=t,t=e[6],e[6]=e[9],e[9]=t,t=e[3],e[3]=e[12],e[12]=t,t=e[7],e[7]=e[13],e[13]=t,t=e[11],e[11]=e[14],e[14]=t,this}setPosition(e,t,a){const i=this.elements;return e.isVector3?(i[12]=e.x,i[13]=e.y,i[14]=e.z):(i[12]=e,i[13]=t,i[14]=a),this}invert(){const e=this.elements,t=e[0],a=e[1],i=e[2],r=e[3],s=e[4],o=e[5],c=e[6],l=e[7],h=e[8],d=e[9],f=e[10],b=e[11],p=e[12],g=e[13],m=e[14],u=e[15],y=d*m*l-g*f*l+g*c*b-o*m*b-d*c*u+o*f*u,x=p*f*l-h*m*l-p*c*b+s*m*b+h*c*u-s*f*u,v=h*g*l-p*d*l+p*o*b-s*g*b-h*o*u+s*d*u,E=p*d*c-h*g*c-p*o*f+s*g*f+h*o*m-s*d*m,_=t*y+a*x+i*v+r*E;if(_===0)return this.set(0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0);const A=1/_;return e[0]=y*A,e[1]=(g*f*r-d*m*r-g*i*b+a*m*b+d*i*u-a*f*u)*A,e[2]=(o*m*r-g*c*r+g*i*l-a*m*l-o*i*u+a*c*u)*A,e[3]=(d*c*r-o*f*r-d*i*l+a*f*l+o*i*b-a*c*b)*A,e[4]=x*A,e[5]=(h*m*r-p*f*r+p*i*b-t*m*b-h*i*u+t*f*u)*A,e[6]=(p*c*r-s*m*r-p*i*l+t*m*l+s*i*u-t*c*u)*A,e[7]=(s*f*r-h*c*r+h*i*l-t*f*l-s*i*b+t*c*b)*A,e[8]=v*A,e[9]=(p*d*r-h*g*r-p*a*b+t*g*b+h*a*u-t*d*u)*A,e[10]=(s*g*r-p*o*r+p*a*l-t*g*l-s*a*u+t*o*u)*A,e[11]=(h*o*r-s*d*r-h*a*l+t*d*l+s*a*b-t*o*b)*A,e[12]=E*A,e[13]=(h*g*i-p*d*i+p*a*f-t*g*f-h*a*m+t*d*m)*A,e[14]=(p*o*i-s*g*i-p*a*c+t*g*c+s*a*m-t*o*m)*A,e[15]=(s*d*i-h*o*i+h*a*c-t*d*c-s*a*f+t*o*f)*A,this}scale(e){const t=this.elements,a=e.x,i=e.y,r=e.z;return t[0]*=a,t[4]*=i,t[8]*=r,t[1]*=a,t[5]*=i,t[9]*=r,t[2]*=a,t[6]*=i,t[10]*=r,t[3]*=a,t[7]*=i,t[11]*=r,this}getMaxScaleOnAxis(){const e=this.elements,t=e[0]*e[0]+e[1]*e[1]+e[2]*e[2],a=e[4]*e[4]+e[5]*e[5]+e[6]*e[6],i=e[8]*e[8]+e[9]*e[9]+e[10]*e[10];return Math.sqrt(Math.max(t,a,i))}makeTranslation(e,t,a){return e.isVector3?this.set(1,0,0,e.x,0,1,0,e.y,0,0,1,e.z,0,0,0,1):this.set(1,0,0,e,0,1,0,t,0,0,1,a,0,0,0,1),this}makeRotationX(e){const t=Math.cos(e),a=Math.sin(e);return this.set(1,0,0,0,0,t,-a,0,0,a,t,0,0,0,0,1),this}makeRotationY(e){const t=Math.cos(e),a=Math.sin(e);return this.set(t,0,a,0,0,1,0,0,-a,0,t,0,0,0,0,1),this}makeRotationZ(e){const t=Math.cos(e),a=Math.sin(e);return this.set(t,-a,0,0,a,t,0,0,0,0,1,0,0,0,0,1),this}makeRotationAxis(e,t){const a=Math.cos(t),i=Math.sin(t),r=1-a,s=e.x,o=e.y,c=e.z,l=r*s,h=r*o;return this.set(l*s+a,l*o-i*c,l*c+i*o,0,l*o+i*c,h*o+a,h*c-i*s,0,l*c-i*o,h*c+i*s,r*c*c+a,0,0,0,0,1),this}makeScale(e,t,a){return this.set(e,0,0,0,0,t,0,0,0,0,a,0,0,0,0,1),this}makeShear(e,t,a,i,r,s){return this.set(1,a,r,0,e,1,s,0,t,i,1,0,0,0,0,1),this}compose(e,t,a){const i=this.elements,r=t._x,s=t._y,o=t._z,c=t._w,l=r+r,h=s+s,d=o+o,f=r*l,b=r*h,p=r*d,g=s*h,m=s*d,u=o*d,y=c*l,x=c*h,v=c*d,E=a.x,_=a.y,A=a.z;return i[0]=(1-(g+u))*E,i[1]=(b+v)*E,i[2]=(p-x)*E,i[3]=0,i[4]=(b-v)*_,i[5]=(1-(f+u))*_,i[6]=(m+y)*_,i[7]=0,i[8]=(p+x)*A,i[9]=(m-y)*A,i[10]=(1-(f+g))*A,i[11]=0,i[12]=e.x,i[13]=e.y,i[14]=e.z,i[15]=1,this}decompose(e,t,a){const i=this.elements;let r=vn.set(i[0],i[1],i[2]).length();const s=vn.set(i[4],i[5],i[6]).length(),o=vn.set(i[8],i[9],i[10]).length();this.determinant()<0&&(r=-r),e.x=i[12],e.y=i[13],e.z=i[14],$t.copy(this);const l=1/r,h=1/s,d=1/o;return $t.elements[0]*=l,$t.elements[1]*=l,$t.elements[2]*=l,$t.elements[4]*=h,$t.elements[5]*=h,$t.elements[6]*=h,$t.elements[8]*=d,$t.elements[9]*=d,$t.elements[10]*=d,t.setFromRotationMatrix($t),a.x=r,a.y=s,a.z=o,this}makePerspective(e,t,a,i,r,s,o=va){const c=this.elements,l=2*r/(t-e),h=2*r/(a-i),d=(t+e)/(t-e),f=(a+i)/(a-i);let b,p;if(o===va)b=-(s+r)/(s-r),p=-2*s*r/(s-r);else if(o===vr)b=-s/(s-r),p=-s*r/(s-r);else throw new Error("THREE.Matrix4.makePerspective(): Invalid coordinate system: "+o);return c[0]=l,c[4]=0,c[8]=d,c[12]=0,c[1]=0,c[5]=h,c[9]=f,c[13]=0,c[2]=0,c[6]=0,c[10]=b,c[14]=p,c[3]=0,c[7]=0,c[11]=-1,c[15]=0,this}makeOrthographic(e,t,a,i,r,s,o=va){const c=this.elements,l=1/(t-e),h=1/(a-i),d=1/(s-r),f=(t+e)*l,b=(a+i)*h;let p,g;if(o===va)p=(s+r)*d,g=-2*d;else if(o===vr)p=r*d,g=-1*d;else throw new Error("THREE.Matrix4.makeOrthographic(): Invalid coordinate system: "+o);return c[0]=2*l,c[4]=0,c[8]=0,c[12]=-f,c[1]=0,c[5]=2*h,c[9]=0,c[13]=-b,c[2]=0,c[6]=0,c[10]=g,c[14]=-p,c[3]=0,c[7]=0,c[11]=0,c[15]=1,this}equals(e){const t=this.elements,a=e.elements;for(let i=0;i<16;i++)if(t[i]!==a[i])return!1;return!0}fromArray(e,t=0){for(let a=0;a<16;a++)this.elements[a]=e[a+t];return this}toArray(e=[],t=0){const a=this.elements;return e[t]=a[0],e[t+1]=a[1],e[t+2]=a[2],e[t+3]=a[3],e[t+4]=a[4],e[t+5]=a[5],e[t+6]=a[6],e[t+7]=a[7],e[t+8]=a[8],e[t+9]=a[9],e[t+10]=a[10],e[t+11]=a[11],e[t+12]=a[12],e[t+13]=a[13],e[t+14]=a[14],e[t+15]=a[15],e}}const vn=new O,$t=new ze,Mb=new O(0,0,0),_b=new O(1,1,1),Na=new O,Fi=new O,Lt=new O,Uc=new ze,Fc=new on;class Aa{constructor(e=0,t=0,a=0,i=Aa.DEFAULT_ORDER){this.isEuler=!0,this._x=e,this._y=t,this._z=a,this._order=i}get x(){return this._x}set x(e){this._x=e,this._onChangeCallback()}get y(){return this._y}set y(e){this._y=e,this._onChangeCallback()}get z(){return this._z}set z(e){this._z=e,this._onChangeCallback()}get order(){return this._order}set order(e){this._order=e,this._onChangeCallback()}set(e,t,a,i=this._order){return this._x=e,this._y=t,this._z=a,this._order=i,this._onChangeCallback(),this}clone(){return new this.constructor(this._x,this._y,this._z,this._order)}copy(e){return this._x=e._x,this._y=e._y,this._z=e._z,this._order=e._order,this._onChangeCallback(),this}setFromRotationMatrix(e,t=this._order,a=!0){const i=e.elements,r=i[0],s=i[4],o=i[8],c=i[1],l=i[5],h=i[9],d=i[2],f=i[6],b=i[10];switch(t){case"XYZ":this._y=Math.asin(Mt(o,-1,1)),Math.abs(o)<.9999999?(this._x=Math.atan2(-h,b),this._z=Math.atan2(-s,r)):(this._x=Math.atan2(f,l),this._z=0);break;case"YXZ":this._x=Math.asin(-Mt(h,-1,1)),Math.abs(h)<.9999999?(this._y=Math.atan2(o,b),this._z=Math.atan2(c,l)):(this._y=Math.atan2(-d,r),this._z=0);break;case"ZXY":this._x=Math.asin(Mt(f,-1,1)),Math.abs(f)<.9999999?(this._y=Math.atan2(-d,b),this._z=Math.atan2(-s,l)):(this._y=0,this._z=Math.atan2(c,r));break;case"ZYX":this._y=Math.asin(-Mt(d,-1,1)),Math.abs(d)<.9999999?(this._x=Math.atan2(f,b),this._z=Math.atan2(c,r)):(this._x=0,this._z=Math.atan2(-s,l));break;case"YZX":this._z=Math.asin(Mt(c,-1,1)),Math.abs(c)<.9999999?(this._x=Math.atan2(-h,l),this._y=Math.atan2(-d,r)):(this._x=0,this._y=Math.atan2(o,b));break;case"XZY":this._z=Math.asin(-Mt(s,-1,1)),Math.abs(s)<.9999999?(this._x=Math.atan2(f,l),this._y=Math.atan2(o,r)):(this._x=Math.atan2(-h,b),this._y=0);break;default:console.warn("THREE.Euler: .setFromRotationMatrix() encountered an unknown order: "+t)}return this._order=t,a===!0&&this._onChangeCallback(),this}setFromQuaternion(e,t,a){return Uc.makeRotationFromQuaternion(e),this.setFromRotationMatrix(Uc,t,a)}setFromVector3(e,t=this._order){return this.set(e.x,e.y,e.z,t)}reorder(e){return Fc.setFromEuler(this),this.setFromQuaternion(Fc,e)}equals(e){return e._x===this._x&&e._y===this._y&&e._z===this._z&&e._order===this._order}fromArray(e){return this._x=e[0],this._y=e[1],this._z=e[2],e[3]!==void 0&&(this._order=e[3]),this._onChangeCallback(),this}toArray(e=[],t=0){return e[t]=this._x,e[t+1]=this._y,e[t+2]=this._z,e[t+3]=this._order,e}_onChange(e){return this._onChangeCallback=e,this}_onChangeCallback(){}*[Symbol.iterator](){yield this._x,yield this._y,yield this._z,yield this._order}}Aa.DEFAULT_ORDER="XYZ";class Ql{constructor(){this.mask=1}set(e){this.mask=(1<<e|0)>>>0}enable(e){this.mask|=1<<e|0}enableAll(){this.mask=-1}toggle(e){this.mask^=1<<e|0}disable(e){this.mask&=~(1<<e|0)}disableAll(){this.mask=0}test(e){return(this.mask&e.mask)!==0}isEnabled(e){return(this.mask&(1<<e|0))!==0}}let Eb=0;const Lc=new O,yn=new on,ua=new ze,Li=new O,$n=new O,Sb=new O,Ab=new on,jc=new O(1,0,0),Oc=new O(0,1,0),zc=new O(0,0,1),Bc={type:"added"},Tb={type:"removed"},xn={type:"childadded",child:null},Xr={type:"childremoved",child:null};class Et extends hn{constructor(){super(),this.isObject3D=!0,Object.defineProperty(this,"id",{value:Eb++}),this.uuid=oa(),this.name="",this.type="Object3D",this.parent=null,this.children=[],this.up=Et.DEFAULT_UP.clone();const e=new O,t=new Aa,a=new on,i=new O(1,1,1);function r(){a.setFromEuler(t,!1)}function s(){t.setFromQuaternion(a,void 0,!1)}t._onChange(r),a._onChange(s),Object.defineProperties(this,{position:{configurable:!0,enumerable:!0,value:e},rotation:{configurable:!0,enumerable:!0,value:t},quaternion:{configurable:!0,enumerable:!0,value:a},scale:{configurable:!0,enumerable:!0,value:i},modelViewMatrix:{value:new ze},normalMatrix:{value:new Pe}}),this.matrix=new ze,this.matrixWorld=new ze,this.matrixAutoUpdate=Et.DEFAULT_MATRIX_AUTO_UPDATE,this.matrixWorldAutoUpdate=Et.DEFAULT_MATRIX_WORLD_AUTO_UPDATE,this.matrixWorldNeedsUpdate=!1,this.layers=new Ql,this.visible=!0,this.castShadow=!1,this.receiveShadow=!1,this.frustumCulled=!0,this.renderOrder=0,this.animations=[],this.userData={}}onBeforeShadow(){}onAfterShadow(){}onBeforeRender(){}onAfterRender(){}applyMatrix4(e){this.matrixAutoUpdate&&this.updateMatrix(),this.matrix.premultiply(e),this.matrix.decompose(this.position,this.quaternion,this.scale)}applyQuaternion(e){return this.quaternion.premultiply(e),this}setRotationFromAxisAngle(e,t){this.quaternion.setFromAxisAngle(e,t)}setRotationFromEuler(e){this.quaternion.setFromEuler(e,!0)}setRotationFromMatrix(e){this.quaternion.setFromRotationMatrix(e)}setRotationFromQuaternion(e){this.quaternion.copy(e)}rotateOnAxis(e,t){return yn.setFromAxisAngle(e,t),this.quaternion.multiply(yn),this}rotateOnWorldAxis(e,t){return yn.setFromAxisAngle(e,t),this.quaternion.premultiply(yn),this}rotateX(e){return this.rotateOnAxis(jc,e)}rotateY(e){return this.rotateOnAxis(Oc,e)}rotateZ(e){return this.rotateOnAxis(zc,e)}translateOnAxis(e,t){return Lc.copy(e).applyQuaternion(this.quaternion),this.position.add(Lc.multiplyScalar(t)),this}translateX(e){return this.translateOnAxis(jc,e)}translateY(e){return this.translateOnAxis(Oc,e)}translateZ(e){return this.translateOnAxis(zc,e)}localToWorld(e){return this.updateWorldMatrix(!0,!1),e.applyMatrix4(this.matrixWorld)}worldToLocal(e){return this.updateWorldMatrix(!0,!1),e.applyMatrix4(ua.copy(this.matrixWorld).invert())}lookAt(e,t,a){e.isVector3?Li.copy(e):Li.set(e,t,a);const i=this.parent;this.updateWorldMatrix(!0,!1),$n.setFromMatrixPosition(this.matrixWorld),this.isCamera||this.isLight?ua.lookAt($n,Li,this.up):ua.lookAt(Li,$n,this.up),this.quaternion.setFromRotationMatrix(ua),i&&(ua.extractRotation(i.matrixWorld),yn.setFromRotationMatrix(ua),this.quaternion.premultiply(yn.invert()))}add(e){if(arguments.length>1){for(let t=0;t<arguments.length;t++)this.add(arguments[t]);return this}return e===this?(console.error("THREE.Object3D.add: object can't be added as a child of itself.",e),this):(e&&e.isObject3D?(e.removeFromParent(),e.parent=this,this.children.push(e),e.dispatchEvent(Bc),xn.child=e,this.dispatchEvent(xn),xn.child=null):console.error("THREE.Object3D.add: object not an instance of THREE.Object3D.",e),this)}remove(e){if(arguments.length>1){for(let a=0;a<arguments.length;a++)this.remove(arguments[a]);return this}const t=this.children.indexOf(e);return t!==-1&&(e.parent=null,this.children.splice(t,1),e.dispatchEvent(Tb),Xr.child=e,this.dispatchEvent(Xr),Xr.child=null),this}removeFromParent(){const e=this.parent;return e!==null&&e.remove(this),this}clear(){return this.remove(...this.children)}attach(e){return this.updateWorldMatrix(!0,!1),ua.copy(this.matrixWorld).invert(),e.parent!==null&&(e.parent.updateWorldMatrix(!0,!1),ua.multiply(e.parent.matrixWorld)),e.applyMatrix4(ua),e.removeFromParent(),e.parent=this,this.children.push(e),e.updateWorldMatrix(!1,!0),e.dispatchEvent(Bc),xn.child=e,this.dispatchEvent(xn),xn.child=null,this}getObjectById(e){return this.getObjectByProperty("id",e)}getObjectByName(e){return this.getObjectByProperty("name",e)}getObjectByProperty(e,t){if(this[e]===t)return this;for(let a=0,i=this.children.length;a<i;a++){const s=this.children[a].getObjectByProperty(e,t);if(s!==void 0)return s}}getObjectsByProperty(e,t,a=[]){this[e]===t&&a.push(this);const i=this.children;for(let r=0,s=i.length;r<s;r++)i[r].getObjectsByProperty(e,t,a);return a}getWorldPosition(e){return this.updateWorldMatrix(!0,!1),e.setFromMatrixPosition(this.matrixWorld)}getWorldQuaternion(e){return this.updateWorldMatrix(!0,!1),this.matrixWorld.decompose($n,e,Sb),e}getWorldScale(e){return this.updateWorldMatrix(!0,!1),this.matrixWorld.decompose($n,Ab,e),e}getWorldDirection(e){this.updateWorldMatrix(!0,!1);const t=this.matrixWorld.elements;return e.set(t[8],t[9],t[10]).normalize()}raycast(){}traverse(e){e(this);const t=this.children;for(let a=0,i=t.length;a<i;a++)t[a].traverse(e)}traverseVisible(e){if(this.visible===!1)return;e(this);const t=this.children;for(let a=0,i=t.length;a<i;a++)t[a].traverseVisible(e)}traverseAncestors(e){const t=this.parent;t!==null&&(e(t),t.traverseAncestors(e))}updateMatrix(){this.matrix.compose(this.position,this.quaternion,this.scale),this.matrixWorldNeedsUpdate=!0}updateMatrixWorld(e){this.matrixAutoUpdate&&this.updateMatrix(),(this.matrixWorldNeedsUpdate||e)&&(this.matrixWorldAutoUpdate===!0&&(this.parent===null?this.matrixWorld.copy(this.matrix):this.matrixWorld.multiplyMatrices(this.parent.matrixWorld,this.matrix)),this.matrixWorldNeedsUpdate=!1,e=!0);const t=this.children;for(let a=0,i=t.length;a<i;a++)t[a].updateMatrixWorld(e)}updateWorldMatrix(e,t){const a=this.parent;if(e===!0&&a!==null&&a.updateWorldMatrix(!0,!1),this.matrixAutoUpdate&&this.updateMatrix(),this.matrixWorldAutoUpdate===!0&&(this.parent===null?this.matrixWorld.copy(this.matrix):this.matrixWorld.multiplyMatrices(this.parent.matrixWorld,this.matrix)),t===!0){const i=this.children;for(let r=0,s=i.length;r<s;r++)i[r].updateWorldMatrix(!1,!0)}}toJSON(e){const t=e===void 0||typeof e=="string",a={};t&&(e={geometries:{},materials:{},textures:{},images:{},shapes:{},skeletons:{},animations:{},nodes:{}},a.metadata={version:4.6,type:"Object",generator:"Object3D.toJSON"});const i={};i.uuid=this.uuid,i.type=this.type,this.name!==""&&(i.name=this.name),this.castShadow===!0&&(i.castShadow=!0),this.receiveShadow===!0&&(i.receiveShadow=!0),this.visible===!1&&(i.visible=!1),this.frustumCulled===!1&&(i.frustumCulled=!1),this.renderOrder!==0&&(i.renderOrder=this.renderOrder),Object.keys(this.userData).length>0&&(i.userData=this.userData),i.layers=this.layers.mask,i.matrix=this.matrix.toArray(),i.up=this.up.toArray(),this.matrixAutoUpdate===!1&&(i.matrixAutoUpdate=!1),this.isInstancedMesh&&(i.type="InstancedMesh",i.count=this.count,i.instanceMatrix=this.instanceMatrix.toJSON(),this.instanceColor!==null&&(i.instanceColor=this.instanceColor.toJSON())),this.isBatchedMesh&&(i.type="BatchedMesh",i.perObjectFrustumCulled=this.perObjectFrustumCulled,i.sortObjects=this.sortObjects,i.drawRanges=this._drawRanges,i.reservedRanges=this._reservedRanges,i.visibility=this._visibility,i.active=this._active,i.bounds=this._bounds.map(o=>({boxInitialized:o.boxInitialized,boxMin:o.box.min.toArray(),boxMax:o.box.max.toArray(),sphereInitialized:o.sphereInitialized,sphereRadius:o.sphere.radius,sphereCenter:o.sphere.center.toArray()})),i.maxInstanceCount=this._maxInstanceCount,i.maxVertexCount=this._maxVertexCount,i.maxIndexCount=this._maxIndexCount,i.geometryInitialized=this._geometryInitialized,i.geometryCount=this._geometryCount,i.matricesTexture=this._matricesTexture.toJSON(e),this._colorsTexture!==null&&(i.colorsTexture=this._colorsTexture.toJSON(e)),this.boundingSphere!==null&&(i.boundingSphere={center:i.boundingSphere.center.toArray(),radius:i.boundingSphere.radius}),this.boundingBox!==null&&(i.boundingBox={min:i.boundingBox.min.toArray(),max:i.boundingBox.max.toArray()}));function r(o,c){return o[c.uuid]===void 0&&(o[c.uuid]=c.toJSON(e)),c.uuid}if(this.isScene)this.background&&(this.background.isColor?i.background=this.background.toJSON():this.background.isTexture&&(i.background=this.background.toJSON(e).uuid)),this.environment&&this.environment.isTexture&&this.environment.isRenderTargetTexture!==!0&&(i.environment=this.environment.toJSON(e).uuid);else if(this.isMesh||this.isLine||this.isPoints){i.geometry=r(e.geometries,this.geometry);const o=this.geometry.parameters;if(o!==void 0&&o.shapes!==void 0){const c=o.shapes;if(Array.isArray(c))for(let l=0,h=c.length;l<h;l++){const d=c[l];r(e.shapes,d)}else r(e.shapes,c)}}if(this.isSkinnedMesh&&(i.bindMode=this.bindMode,i.bindMatrix=this.bindMatrix.toArray(),this.skeleton!==void 0&&(r(e.skeletons,this.skeleton),i.skeleton=this.skeleton.uuid)),this.material!==void 0)if(Array.isArray(this.material)){const o=[];for(let c=0,l=this.material.length;c<l;c++)o.push(r(e.materials,this.material[c]));i.material=o}else i.material=r(e.materials,this.material);if(this.children.length>0){i.children=[];for(let o=0;o<this.children.length;o++)i.children.push(this.children[o].toJSON(e).object)}if(this.animations.length>0){i.animations=[];for(let o=0;o<this.animations.length;o++){const c=this.animations[o];i.animations.push(r(e.animations,c))}}if(t){const o=s(e.geometries),c=s(e.materials),l=s(e.textures),h=s(e.images),d=s(e.shapes),f=s(e.skeletons),b=s(e.animations),p=s(e.nodes);o.length>0&&(a.geometries=o),c.length>0&&(a.materials=c),l.length>0&&(a.textures=l),h.length>0&&(a.images=h),d.length>0&&(a.shapes=d),f.length>0&&(a.skeletons=f),b.length>0&&(a.animations=b),p.length>0&&(a.nodes=p)}return a.object=i,a;function s(o){const c=[];for(const l in o){const h=o[l];delete h.metadata,c.push(h)}return c}}clone(e){return new this.constructor().copy(this,e)}copy(e,t=!0){if(this.name=e.name,this.up.copy(e.up),this.position.copy(e.position),this.rotation.order=e.rotation.order,this.quaternion.copy(e.quaternion),this.scale.copy(e.scale),this.matrix.copy(e.matrix),this.matrixWorld.copy(e.matrixWorld),this.matrixAutoUpdate=e.matrixAutoUpdate,this.matrixWorldAutoUpdate=e.matrixWorldAutoUpdate,this.matrixWorldNeedsUpdate=e.matrixWorldNeedsUpdate,this.layers.mask=e.layers.mask,this.visible=e.visible,this.castShadow=e.castShadow,this.receiveShadow=e.receiveShadow,this.frustumCulled=e.frustumCulled,this.renderOrder=e.renderOrder,this.animations=e.animations.slice(),this.userData=JSON.parse(JSON.stringify(e.userData)),t===!0)for(let a=0;a<e.children.length;a++){const i=e.children[a];this.add(i.clone())}return this}}Et.DEFAULT_UP=new O(0,1,0);Et.DEFAULT_MATRIX_AUTO_UPDATE=!0;Et.DEFAULT_MATRIX_WORLD_AUTO_UPDATE=!0;const ea=new O,ba=new O,Kr=new O,ma=new O,wn=new O,Mn=new O,Gc=new O,Jr=new O,Yr=new O,Zr=new O,Qr=new ot,$r=new ot,es=new ot;class aa{constructor(e=new O,t=new O,a=new O){this.a=e,this.b=t,this.c=a}static getNormal(e,t,a,i){i.subVectors(a,t),ea.subVectors(e,t),i.cross(ea);const r=i.lengthSq();return r>0?i.multiplyScalar(1/Math.sqrt(r)):i.set(0,0,0)}static getBarycoord(e,t,a,i,r){ea.subVectors(i,t),ba.subVectors(a,t),Kr.subVectors(e,t);const s=ea.dot(ea),o=ea.dot(ba),c=ea.dot(Kr),l=ba.dot(ba),h=ba.dot(Kr),d=s*l-o*o;if(d===0)return r.set(0,0,0),null;const f=1/d,b=(l*c-o*h)*f,p=(s*h-o*c)*f;return r.set(1-b-p,p,b)}static containsPoint(e,t,a,i){return this.getBarycoord(e,t,a,i,ma)===null?!1:ma.x>=0&&ma.y>=0&&ma.x+ma.y<=1}static getInterpolation(e,t,a,i,r,s,o,c){return this.getBarycoord(e,t,a,i,ma)===null?(c.x=0,c.y=0,"z"in c&&(c.z=0),"w"in c&&(c.w=0),null):(c.setScalar(0),c.addScaledVector(r,ma.x),c.addScaledVector(s,ma.y),c.addScaledVector(o,ma.z),c)}static getInterpolatedAttribute(e,t,a,i,r,s){return Qr.setScalar(0),$r.setScalar(0),es.setScalar(0),Qr.fromBufferAttribute(e,t),$r.fromBufferAttribute(e,a),es.fromBufferAttribute(e,i),s.setScalar(0),s.addScaledVector(Qr,r.x),s.addScaledVector($r,r.y),s.addScaledVector(es,r.z),s}static isFrontFacing(e,t,a,i){return ea.subVectors(a,t),ba.subVectors(e,t),ea.cross(ba).dot(i)<0}set(e,t,a){return this.a.copy(e),this.b.copy(t),this.c.copy(a),this}setFromPointsAndIndices(e,t,a,i){return this.a.copy(e[t]),this.b.copy(e[a]),this.c.copy(e[i]),this}setFromAttributeAndIndices(e,t,a,i){return this.a.fromBufferAttribute(e,t),this.b.fromBufferAttribute(e,a),this.c.fromBufferAttribute(e,i),this}clone(){return new this.constructor().copy(this)}copy(e){return this.a.copy(e.a),this.b.copy(e.b),this.c.copy(e.c),this}getArea(){return ea.subVectors(this.c,this.b),ba.subVectors(this.a,this.b),ea.cross(ba).length()*.5}getMidpoint(e){return e.addVectors(this.a,this.b).add(this.c).multiplyScalar(1/3)}getNormal(e){return aa.getNormal(this.a,this.b,this.c,e)}getPlane(e){return e.setFromCoplanarPoints(this.a,this.b,this.c)}getBarycoord(e,t){return aa.getBarycoord(e,this.a,this.b,this.c,t)}getInterpolation(e,t,a,i,r){return aa.getInterpolation(e,this.a,this.b,this.c,t,a,i,r)}containsPoint(e){return aa.containsPoint(e,this.a,this.b,this.c)}isFrontFacing(e){return aa.isFrontFacing(this.a,this.b,this.c,e)}intersectsBox(e){return e.intersectsTriangle(this)}closestPointToPoint(e,t){const a=this.a,i=this.b,r=this.c;let s,o;wn.subVectors(i,a),Mn.subVectors(r,a),Jr.subVectors(e,a);const c=wn.dot(Jr),l=Mn.dot(Jr);if(c<=0&&l<=0)return t.copy(a);Yr.subVectors(e,i);const h=wn.dot(Yr),d=Mn.dot(Yr);if(h>=0&&d<=h)return t.copy(i);const f=c*d-h*l;if(f<=0&&c>=0&&h<=0)return s=c/(c-h),t.copy(a).addScaledVector(wn,s);Zr.subVectors(e,r);const b=wn.dot(Zr),p=Mn.dot(Zr);if(p>=0&&b<=p)return t.copy(r);const g=b*l-c*p;if(g<=0&&l>=0&&p<=0)return o=l/(l-p),t.copy(a).addScaledVector(Mn,o);const m=h*p-b*d;if(m<=0&&d-h>=0&&b-p>=0)return Gc.subVectors(r,i),o=(d-h)/(d-h+(b-p)),t.copy(i).addScaledVector(Gc,o);const u=1/(m+g+f);return s=g*u,o=f*u,t.copy(a).addScaledVector(wn,s).addScaledVector(Mn,o)}equals(e){return e.a.equals(this.a)&&e.b.equals(this.b)&&e.c.equals(this.c)}}const $l={aliceblue:15792383,antiquewhite:16444375,aqua:65535,aquamarine:8388564,azure:15794175,beige:16119260,bisque:16770244,black:0,blanchedalmond:16772045,blue:255,blueviolet:9055202,brown:10824234,burlywood:14596231,cadetblue:6266528,chartreuse:8388352,chocolate:13789470,coral:16744272,cornflowerblue:6591981,cornsilk:16775388,crimson:14423100,cyan:65535,darkblue:139,darkcyan:35723,darkgoldenrod:12092939,darkgray:11119017,darkgreen:25600,darkgrey:11119017,darkkhaki:12433259,darkmagenta:9109643,darkolivegreen:5597999,darkorange:16747520,darkorchid:10040012,darkred:9109504,darksalmon:15308410,darkseagreen:9419919,darkslateblue:4734347,darkslategray:3100495,darkslategrey:3100495,darkturquoise:52945,darkviolet:9699539,deeppink:16716947,deepskyblue:49151,dimgray:6908265,dimgrey:6908265,dodgerblue:2003199,firebrick:11674146,floralwhite:16775920,forestgreen:2263842,fuchsia:16711935,gainsboro:14474460,ghostwhite:16316671,gold:16766720,goldenrod:14329120,gray:8421504,green:32768,greenyellow:11403055,grey:8421504,honeydew:15794160,hotpink:16738740,indianred:13458524,indigo:4915330,ivory:16777200,khaki:15787660,lavender:15132410,lavenderblush:16773365,lawngreen:8190976,lemonchiffon:16775885,lightblue:11393254,lightcoral:15761536,lightcyan:14745599,lightgoldenrodyellow:16448210,lightgray:13882323,lightgreen:9498256,lightgrey:13882323,lightpink:16758465,lightsalmon:16752762,lightseagreen:2142890,lightskyblue:8900346,lightslategray:7833753,lightslategrey:7833753,lightsteelblue:11584734,lightyellow:16777184,lime:65280,limegreen:3329330,linen:16445670,magenta:16711935,maroon:8388608,mediumaquamarine:6737322,mediumblue:205,mediumorchid:12211667,mediumpurple:9662683,mediumseagreen:3978097,mediumslateblue:8087790,mediumspringgreen:64154,mediumturquoise:4772300,mediumvioletred:13047173,midnightblue:1644912,mintcream:16121850,mistyrose:16770273,moccasin:16770229,navajowhite:16768685,navy:128,oldlace:16643558,olive:8421376,olivedrab:7048739,orange:16753920,orangered:16729344,orchid:14315734,palegoldenrod:15657130,palegreen:10025880,paleturquoise:11529966,palevioletred:14381203,papayawhip:16773077,peachpuff:16767673,peru:13468991,pink:16761035,plum:14524637,powderblue:11591910,purple:8388736,rebeccapurple:6697881,red:16711680,rosybrown:12357519,royalblue:4286945,saddlebrown:9127187,salmon:16416882,sandybrown:16032864,seagreen:3050327,seashell:16774638,sienna:10506797,silver:12632256,skyblue:8900331,slateblue:6970061,slategray:7372944,slategrey:7372944,snow:16775930,springgreen:65407,steelblue:4620980,tan:13808780,teal:32896,thistle:14204888,tomato:16737095,turquoise:4251856,violet:15631086,wheat:16113331,white:16777215,whitesmoke:16119285,yellow:16776960,yellowgreen:10145074},Ua={h:0,s:0,l:0},ji={h:0,s:0,l:0};function ts(n,e,t){return t<0&&(t+=1),t>1&&(t-=1),t<1/6?n+(e-n)*6*t:t<1/2?e:t<2/3?n+(e-n)*6*(2/3-t):n}class Ve{constructor(e,t,a){return this.isColor=!0,this.r=1,this.g=1,this.b=1,this.set(e,t,a)}set(e,t,a){if(t===void 0&&a===void 0){const i=e;i&&i.isColor?this.copy(i):typeof i=="number"?this.setHex(i):typeof i=="string"&&this.setStyle(i)}else this.setRGB(e,t,a);return this}setScalar(e){return this.r=e,this.g=e,this.b=e,this}setHex(e,t=kt){return e=Math.floor(e),this.r=(e>>16&255)/255,this.g=(e>>8&255)/255,this.b=(e&255)/255,qe.toWorkingColorSpace(this,t),this}setRGB(e,t,a,i=qe.workingColorSpace){return this.r=e,this.g=t,this.b=a,qe.toWorkingColorSpace(this,i),this}setHSL(e,t,a,i=qe.workingColorSpace){if(e=Oo(e,1),t=Mt(t,0,1),a=Mt(a,0,1),t===0)this.r=this.g=this.b=a;else{const r=a<=.5?a*(1+t):a+t-a*t,s=2*a-r;this.r=ts(s,r,e+1/3),this.g=ts(s,r,e),this.b=ts(s,r,e-1/3)}return qe.toWorkingColorSpace(this,i),this}setStyle(e,t=kt){function a(r){r!==void 0&&parseFloat(r)<1&&console.warn("THREE.Color: Alpha component of "+e+" will be ignored.")}let i;if(i=/^(\w+)\(([^\)]*)\)/.exec(e)){let r;const s=i[1],o=i[2];switch(s){case"rgb":case"rgba":if(r=/^\s*(\d+)\s*,\s*(\d+)\s*,\s*(\d+)\s*(?:,\s*(\d*\.?\d+)\s*)?$/.exec(o))return a(r[4]),this.setRGB(Math.min(255,parseInt(r[1],10))/255,Math.min(255,parseInt(r[2],10))/255,Math.min(255,parseInt(r[3],10))/255,t);if(r=/^\s*(\d+)\%\s*,\s*(\d+)\%\s*,\s*(\d+)\%\s*(?:,\s*(\d*\.?\d+)\s*)?$/.exec(o))return a(r[4]),this.setRGB(Math.min(100,parseInt(r[1],10))/100,Math.min(100,parseInt(r[2],10))/100,Math.min(100,parseInt(r[3],10))/100,t);break;case"hsl":case"hsla":if(r=/^\s*(\d*\.?\d+)\s*,\s*(\d*\.?\d+)\%\s*,\s*(\d*\.?\d+)\%\s*(?:,\s*(\d*\.?\d+)\s*)?$/.exec(o))return a(r[4]),this.setHSL(parseFloat(r[1])/360,parseFloat(r[2])/100,parseFloat(r[3])/100,t);break;default:console.warn("THREE.Color: Unknown color model "+e)}}else if(i=/^\#([A-Fa-f\d]+)$/.exec(e)){const r=i[1],s=r.length;if(s===3)return this.setRGB(parseInt(r.charAt(0),16)/15,parseInt(r.charAt(1),16)/15,parseInt(r.charAt(2),16)/15,t);if(s===6)return this.setHex(parseInt(r,16),t);console.warn("THREE.Color: Invalid hex color "+e)}else if(e&&e.length>0)return this.setColorName(e,t);return this}setColorName(e,t=kt){const a=$l[e.toLowerCase()];return a!==void 0?this.setHex(a,t):console.warn("THREE.Color: Unknown color "+e),this}clone(){return new this.constructor(this.r,this.g,this.b)}copy(e){return this.r=e.r,this.g=e.g,this.b=e.b,this}copySRGBToLinear(e){return this.r=ya(e.r),this.g=ya(e.g),this.b=ya(e.b),this}copyLinearToSRGB(e){return this.r=Nn(e.r),this.g=Nn(e.g),this.b=Nn(e.b),this}convertSRGBToLinear(){return this.copySRGBToLinear(this),this}convertLinearToSRGB(){return this.copyLinearToSRGB(this),this}getHex(e=kt){return qe.fromWorkingColorSpace(wt.copy(this),e),Math.round(Mt(wt.r*255,0,255))*65536+Math.round(Mt(wt.g*255,0,255))*256+Math.round(Mt(wt.b*255,0,255))}getHexString(e=kt){return("000000"+this.getHex(e).toString(16)).slice(-6)}getHSL(e,t=qe.workingColorSpace){qe.fromWorkingColorSpace(wt.copy(this),t);const a=wt.r,i=wt.g,r=wt.b,s=Math.max(a,i,r),o=Math.min(a,i,r);let c,l;const h=(o+s)/2;if(o===s)c=0,l=0;else{const d=s-o;switch(l=h<=.5?d/(s+o):d/(2-s-o),s){case a:c=(i-r)/d+(i<r?6:0);break;case i:c=(r-a)/d+2;break;case r:c=(a-i)/d+4;break}c/=6}return e.h=c,e.s=l,e.l=h,e}getRGB(e,t=qe.workingColorSpace){return qe.fromWorkingColorSpace(wt.copy(this),t),e.r=wt.r,e.g=wt.g,e.b=wt.b,e}getStyle(e=kt){qe.fromWorkingColorSpace(wt.copy(this),e);const t=wt.r,a=wt.g,i=wt.b;return e!==kt?`color(${e} ${t.toFixed(3)} ${a.toFixed(3)} ${i.toFixed(3)})`:`rgb(${Math.round(t*255)},${Math.round(a*255)},${Math.round(i*255)})`}offsetHSL(e,t,a){return this.getHSL(Ua),this.setHSL(Ua.h+e,Ua.s+t,Ua.l+a)}add(e){return this.r+=e.r,this.g+=e.g,this.b+=e.b,this}addColors(e,t){return this.r=e.r+t.r,this.g=e.g+t.g,this.b=e.b+t.b,this}addScalar(e){return this.r+=e,this.g+=e,this.b+=e,this}sub(e){return this.r=Math.max(0,this.r-e.r),this.g=Math.max(0,this.g-e.g),this.b=Math.max(0,this.b-e.b),this}multiply(e){return this.r*=e.r,this.g*=e.g,this.b*=e.b,this}multiplyScalar(e){return this.r*=e,this.g*=e,this.b*=e,this}lerp(e,t){return this.r+=(e.r-this.r)*t,this.g+=(e.g-this.g)*t,this.b+=(e.b-this.b)*t,this}lerpColors(e,t,a){return this.r=e.r+(t.r-e.r)*a,this.g=e.g+(t.g-e.g)*a,this.b=e.b+(t.b-e.b)*a,this}lerpHSL(e,t){this.getHSL(Ua),e.getHSL(ji);const a=mi(Ua.h,ji.h,t),i=mi(Ua.s,ji.s,t),r=mi(Ua.l,ji.l,t);return this.setHSL(a,i,r),this}setFromVector3(e){return this.r=e.x,this.g=e.y,this.b=e.z,this}applyMatrix3(e){const t=this.r,a=this.g,i=this.b,r=e.elements;return this.r=r[0]*t+r[3]*a+r[6]*i,this.g=r[1]*t+r[4]*a+r[7]*i,this.b=r[2]*t+r[5]*a+r[8]*i,this}equals(e){return e.r===this.r&&e.g===this.g&&e.b===this.b}fromArray(e,t=0){return this.r=e[t],this.g=e[t+1],this.b=e[t+2],this}toArray(e=[],t=0){return e[t]=this.r,e[t+1]=this.g,e[t+2]=this.b,e}fromBufferAttribute(e,t){return this.r=e.getX(t),this.g=e.getY(t),this.b=e.getZ(t),this}toJSON(){return this.getHex()}*[Symbol.iterator](){yield this.r,yield this.g,yield this.b}}const wt=new Ve;Ve.NAMES=$l;let kb=0;class Vn extends hn{static get type(){return"Material"}get type(){return this.constructor.type}set type(e){}constructor(){super(),this.isMaterial=!0,Object.defineProperty(this,"id",{value:kb++}),this.uuid=oa(),this.name="",this.blending=Pn,this.side=Ma,this.vertexColors=!1,this.opacity=1,this.transparent=!1,this.alphaHash=!1,this.blendSrc=Is,this.blendDst=Ps,this.blendEquation=en,this.blendSrcAlpha=null,this.blendDstAlpha=null,this.blendEquationAlpha=null,this.blendColor=new Ve(0,0,0),this.blendAlpha=0,this.depthFunc=Un,this.depthTest=!0,this.depthWrite=!0,this.stencilWriteMask=255,this.stencilFunc=Ac,this.stencilRef=0,this.stencilFuncMask=255,this.stencilFail=un,this.stencilZFail=un,this.stencilZPass=un,this.stencilWrite=!1,this.clippingPlanes=null,this.clipIntersection=!1,this.clipShadows=!1,this.shadowSide=null,this.colorWrite=!0,this.precision=null,this.polygonOffset=!1,this.polygonOffsetFactor=0,this.polygonOffsetUnits=0,this.dithering=!1,this.alphaToCoverage=!1,this.premultipliedAlpha=!1,this.forceSinglePass=!1,this.visible=!0,this.toneMapped=!0,this.userData={},this.version=0,this._alphaTest=0}get alphaTest(){return this._alphaTest}set alphaTest(e){this._alphaTest>0!=e>0&&this.version++,this._alphaTest=e}onBeforeRender(){}onBeforeCompile(){}customProgramCacheKey(){return this.onBeforeCompile.toString()}setValues(e){if(e!==void 0)for(const t in e){const a=e[t];if(a===void 0){console.warn(`THREE.Material: parameter '${t}' has value of undefined.`);continue}const i=this[t];if(i===void 0){console.warn(`THREE.Material: '${t}' is not a property of THREE.${this.type}.`);continue}i&&i.isColor?i.set(a):i&&i.isVector3&&a&&a.isVector3?i.copy(a):this[t]=a}}toJSON(e){const t=e===void 0||typeof e=="string";t&&(e={textures:{},images:{}});const a={metadata:{version:4.6,type:"Material",generator:"Material.toJSON"}};a.uuid=this.uuid,a.type=this.type,this.name!==""&&(a.name=this.name),this.color&&this.color.isColor&&(a.color=this.color.getHex()),this.roughness!==void 0&&(a.roughness=this.roughness),this.metalness!==void 0&&(a.metalness=this.metalness),this.sheen!==void 0&&(a.sheen=this.sheen),this.sheenColor&&this.sheenColor.isColor&&(a.sheenColor=this.sheenColor.getHex()),this.sheenRoughness!==void 0&&(a.sheenRoughness=this.sheenRoughness),this.emissive&&this.emissive.isColor&&(a.emissive=this.emissive.getHex()),this.emissiveIntensity!==void 0&&this.emissiveIntensity!==1&&(a.emissiveIntensity=this.emissiveIntensity),this.specular&&this.specular.isColor&&(a.specular=this.specular.getHex()),this.specularIntensity!==void 0&&(a.specularIntensity=this.specularIntensity),this.specularColor&&this.specularColor.isColor&&(a.specularColor=this.specularColor.getHex()),this.shininess!==void 0&&(a.shininess=this.shininess),this.clearcoat!==void 0&&(a.clearcoat=this.clearcoat),this.clearcoatRoughness!==void 0&&(a.clearcoatRoughness=this.clearcoatRoughness),this.clearcoatMap&&this.clearcoatMap.isTexture&&(a.clearcoatMap=this.clearcoatMap.toJSON(e).uuid),this.clearcoatRoughnessMap&&this.clearcoatRoughnessMap.isTexture&&(a.clearcoatRoughnessMap=this.clearcoatRoughnessMap.toJSON(e).uuid),this.clearcoatNormalMap&&this.clearcoatNormalMap.isTexture&&(a.clearcoatNormalMap=this.clearcoatNormalMap.toJSON(e).uuid,a.clearcoatNormalScale=this.clearcoatNormalScale.toArray()),this.dispersion!==void 0&&(a.dispersion=this.dispersion),this.iridescence!==void 0&&(a.iridescence=this.iridescence),this.iridescenceIOR!==void 0&&(a.iridescenceIOR=this.iridescenceIOR),this.iridescenceThicknessRange!==void 0&&(a.iridescenceThicknessRange=this.iridescenceThicknessRange),this.iridescenceMap&&this.iridescenceMap.isTexture&&(a.iridescenceMap=this.iridescenceMap.toJSON(e).uuid),this.iridescenceThicknessMap&&this.iridescenceThicknessMap.isTexture&&(a.iridescenceThicknessMap=this.iridescenceThicknessMap.toJSON(e).uuid),this.anisotropy!==void 0&&(a.anisotropy=this.anisotropy),this.anisotropyRotation!==void 0&&(a.anisotropyRotation=this.anisotropyRotation),this.anisotropyMap&&this.anisotropyMap.isTexture&&(a.anisotropyMap=this.anisotropyMap.toJSON(e).uuid),this.map&&this.map.isTexture&&(a.map=this.map.toJSON(e).uuid),this.matcap&&this.matcap.isTexture&&(a.matcap=this.matcap.toJSON(e).uuid),this.alphaMap&&this.alphaMap.isTexture&&(a.alphaMap=this.alphaMap.toJSON(e).uuid),this.lightMap&&this.lightMap.isTexture&&(a.lightMap=this.lightMap.toJSON(e).uuid,a.lightMapIntensity=this.lightMapIntensity),this.aoMap&&this.aoMap.isTexture&&(a.aoMap=this.aoMap.toJSON(e).uuid,a.aoMapIntensity=this.aoMapIntensity),this.bumpMap&&this.bumpMap.isTexture&&(a.bumpMap=this.bumpMap.toJSON(e).uuid,a.bumpScale=this.bumpScale),this.normalMap&&this.normalMap.isTexture&&(a.normalMap=this.normalMap.toJSON(e).uuid,a.normalMapType=this.normalMapType,a.normalScale=this.normalScale.toArray()),this.displacementMap&&this.displacementMap.isTexture&&(a.displacementMap=this.displacementMap.toJSON(e).uuid,a.displacementScale=this.displacementScale,a.displacementBias=this.displacementBias),this.roughnessMap&&this.roughnessMap.isTexture&&(a.roughnessMap=this.roughnessMap.toJSON(e).uuid),this.metalnessMap&&this.metalnessMap.isTexture&&(a.metalnessMap=this.metalnessMap.toJSON(e).uuid),this.emissiveMap&&this.emissiveMap.isTexture&&(a.emissiveMap=this.emissiveMap.toJSON(e).uuid),this.specularMap&&this.specularMap.isTexture&&(a.specularMap=this.specularMap.toJSON(e).uuid),this.specularIntensityMap&&this.specularIntensityMap.isTexture&&(a.specularIntensityMap=this.specularIntensityMap.toJSON(e).uuid),this.specularColorMap&&this.specularColorMap.isTexture&&(a.specularColorMap=this.specularColorMap.toJSON(e).uuid),this.envMap&&this.envMap.isTexture&&(a.envMap=this.envMap.toJSON(e).uuid,this.combine!==void 0&&(a.combine=this.combine)),this.envMapRotation!==void 0&&(a.envMapRotation=this.envMapRotation.toArray()),this.envMapIntensity!==void 0&&(a.envMapIntensity=this.envMapIntensity),this.reflectivity!==void 0&&(a.reflectivity=this.reflectivity),this.refractionRatio!==void 0&&(a.refractionRatio=this.refractionRatio),this.gradientMap&&this.gradientMap.isTexture&&(a.gradientMap=this.gradientMap.toJSON(e).uuid),this.transmission!==void 0&&(a.transmission=this.transmission),this.transmissionMap&&this.transmissionMap.isTexture&&(a.transmissionMap=this.transmissionMap.toJSON(e).uuid),this.thickness!==void 0&&(a.thickness=this.thickness),this.thicknessMap&&this.thicknessMap.isTexture&&(a.thicknessMap=this.thicknessMap.toJSON(e).uuid),this.attenuationDistance!==void 0&&this.attenuationDistance!==1/0&&(a.attenuationDistance=this.attenuationDistance),this.attenuationColor!==void 0&&(a.attenuationColor=this.attenuationColor.getHex()),this.size!==void 0&&(a.size=this.size),this.shadowSide!==null&&(a.shadowSide=this.shadowSide),this.sizeAttenuation!==void 0&&(a.sizeAttenuation=this.sizeAttenuation),this.blending!==Pn&&(a.blending=this.blending),this.side!==Ma&&(a.side=this.side),this.vertexColors===!0&&(a.vertexColors=!0),this.opacity<1&&(a.opacity=this.opacity),this.transparent===!0&&(a.transparent=!0),this.blendSrc!==Is&&(a.blendSrc=this.blendSrc),this.blendDst!==Ps&&(a.blendDst=this.blendDst),this.blendEquation!==en&&(a.blendEquation=this.blendEquation),this.blendSrcAlpha!==null&&(a.blendSrcAlpha=this.blendSrcAlpha),this.blendDstAlpha!==null&&(a.blendDstAlpha=this.blendDstAlpha),this.blendEquationAlpha!==null&&(a.blendEquationAlpha=this.blendEquationAlpha),this.blendColor&&this.blendColor.isColor&&(a.blendColor=this.blendColor.getHex()),this.blendAlpha!==0&&(a.blendAlpha=this.blendAlpha),this.depthFunc!==Un&&(a.depthFunc=this.depthFunc),this.depthTest===!1&&(a.depthTest=this.depthTest),this.depthWrite===!1&&(a.depthWrite=this.depthWrite),this.colorWrite===!1&&(a.colorWrite=this.colorWrite),this.stencilWriteMask!==255&&(a.stencilWriteMask=this.stencilWriteMask),this.stencilFunc!==Ac&&(a.stencilFunc=this.stencilFunc),this.stencilRef!==0&&(a.stencilRef=this.stencilRef),this.stencilFuncMask!==255&&(a.stencilFuncMask=this.stencilFuncMask),this.stencilFail!==un&&(a.stencilFail=this.stencilFail),this.stencilZFail!==un&&(a.stencilZFail=this.stencilZFail),this.stencilZPass!==un&&(a.stencilZPass=this.stencilZPass),this.stencilWrite===!0&&(a.stencilWrite=this.stencilWrite),this.rotation!==void 0&&this.rotation!==0&&(a.rotation=this.rotation),this.polygonOffset===!0&&(a.polygonOffset=!0),this.polygonOffsetFactor!==0&&(a.polygonOffsetFactor=this.polygonOffsetFactor),this.polygonOffsetUnits!==0&&(a.polygonOffsetUnits=this.polygonOffsetUnits),this.linewidth!==void 0&&this.linewidth!==1&&(a.linewidth=this.linewidth),this.dashSize!==void 0&&(a.dashSize=this.dashSize),this.gapSize!==void 0&&(a.gapSize=this.gapSize),this.scale!==void 0&&(a.scale=this.scale),this.dithering===!0&&(a.dithering=!0),this.alphaTest>0&&(a.alphaTest=this.alphaTest),this.alphaHash===!0&&(a.alphaHash=!0),this.alphaToCoverage===!0&&(a.alphaToCoverage=!0),this.premultipliedAlpha===!0&&(a.premultipliedAlpha=!0),this.forceSinglePass===!0&&(a.forceSinglePass=!0),this.wireframe===!0&&(a.wireframe=!0),this.wireframeLinewidth>1&&(a.wireframeLinewidth=this.wireframeLinewidth),this.wireframeLinecap!=="round"&&(a.wireframeLinecap=this.wireframeLinecap),this.wireframeLinejoin!=="round"&&(a.wireframeLinejoin=this.wireframeLinejoin),this.flatShading===!0&&(a.flatShading=!0),this.visible===!1&&(a.visible=!1),this.toneMapped===!1&&(a.toneMapped=!1),this.fog===!1&&(a.fog=!1),Object.keys(this.userData).length>0&&(a.userData=this.userData);function i(r){const s=[];for(const o in r){const c=r[o];delete c.metadata,s.push(c)}return s}if(t){const r=i(e.textures),s=i(e.images);r.length>0&&(a.textures=r),s.length>0&&(a.images=s)}return a}clone(){return new this.constructor().copy(this)}copy(e){this.name=e.name,this.blending=e.blending,this.side=e.side,this.vertexColors=e.vertexColors,this.opacity=e.opacity,this.transparent=e.transparent,this.blendSrc=e.blendSrc,this.blendDst=e.blendDst,this.blendEquation=e.blendEquation,this.blendSrcAlpha=e.blendSrcAlpha,this.blendDstAlpha=e.blendDstAlpha,this.blendEquationAlpha=e.blendEquationAlpha,this.blendColor.copy(e.blendColor),this.blendAlpha=e.blendAlpha,this.depthFunc=e.depthFunc,this.depthTest=e.depthTest,this.depthWrite=e.depthWrite,this.stencilWriteMask=e.stencilWriteMask,this.stencilFunc=e.stencilFunc,this.stencilRef=e.stencilRef,this.stencilFuncMask=e.stencilFuncMask,this.stencilFail=e.stencilFail,this.stencilZFail=e.stencilZFail,this.stencilZPass=e.stencilZPass,this.stencilWrite=e.stencilWrite;const t=e.clippingPlanes;let a=null;if(t!==null){const i=t.length;a=new Array(i);for(let r=0;r!==i;++r)a[r]=t[r].clone()}return this.clippingPlanes=a,this.clipIntersection=e.clipIntersection,this.clipShadows=e.clipShadows,this.shadowSide=e.shadowSide,this.colorWrite=e.colorWrite,this.precision=e.precision,this.polygonOffset=e.polygonOffset,this.polygonOffsetFactor=e.polygonOffsetFactor,this.polygonOffsetUnits=e.polygonOffsetUnits,this.dithering=e.dithering,this.alphaTest=e.alphaTest,this.alphaHash=e.alphaHash,this.alphaToCoverage=e.alphaToCoverage,this.premultipliedAlpha=e.premultipliedAlpha,this.forceSinglePass=e.forceSinglePass,this.visible=e.visible,this.toneMapped=e.toneMapped,this.userData=JSON.parse(JSON.stringify(e.userData)),this}dispose(){this.dispatchEvent({type:"dispose"})}set needsUpdate(e){e===!0&&this.version++}onBuild(){console.warn("Material: onBuild() has been removed.")}}class ed extends Vn{static get type(){return"MeshBasicMaterial"}constructor(e){super(),this.isMeshBasicMaterial=!0,this.color=new Ve(16777215),this.map=null,this.lightMap=null,this.lightMapIntensity=1,this.aoMap=null,this.aoMapIntensity=1,this.specularMap=null,this.alphaMap=null,this.envMap=null,this.envMapRotation=new Aa,this.combine=Dl,this.reflectivity=1,this.refractionRatio=.98,this.wireframe=!1,this.wireframeLinewidth=1,this.wireframeLinecap="round",this.wireframeLinejoin="round",this.fog=!0,this.setValues(e)}copy(e){return super.copy(e),this.color.copy(e.color),this.map=e.map,this.lightMap=e.lightMap,this.lightMapIntensity=e.lightMapIntensity,this.aoMap=e.aoMap,this.aoMapIntensity=e.aoMapIntensity,this.specularMap=e.specularMap,this.alphaMap=e.alphaMap,this.envMap=e.envMap,this.envMapRotation.copy(e.envMapRotation),this.combine=e.combine,this.reflectivity=e.reflectivity,this.refractionRatio=e.refractionRatio,this.wireframe=e.wireframe,this.wireframeLinewidth=e.wireframeLinewidth,this.wireframeLinecap=e.wireframeLinecap,this.wireframeLinejoin=e.wireframeLinejoin,this.fog=e.fog,this}}const ht=new O,Oi=new De;class Be{constructor(e,t,a=!1){if(Array.isArray(e))throw new TypeError("THREE.BufferAttribute: array should be a Typed Array.");this.isBufferAttribute=!0,this.name="",this.array=e,this.itemSize=t,this.count=e!==void 0?e.length/t:0,this.normalized=a,this.usage=po,this.updateRanges=[],this.gpuType=zt,this.version=0}onUploadCallback(){}set needsUpdate(e){e===!0&&this.version++}setUsage(e){return this.usage=e,this}addUpdateRange(e,t){this.updateRanges.push({start:e,count:t})}clearUpdateRanges(){this.updateRanges.length=0}copy(e){return this.name=e.name,this.array=new e.array.constructor(e.array),this.itemSize=e.itemSize,this.count=e.count,this.normalized=e.normalized,this.usage=e.usage,this.gpuType=e.gpuType,this}copyAt(e,t,a){e*=this.itemSize,a*=t.itemSize;for(let i=0,r=this.itemSize;i<r;i++)this.array[e+i]=t.array[a+i];return this}copyArray(e){return this.array.set(e),this}applyMatrix3(e){if(this.itemSize===2)for(let t=0,a=this.count;t<a;t++)Oi.fromBufferAttribute(this,t),Oi.applyMatrix3(e),this.setXY(t,Oi.x,Oi.y);else if(this.itemSize===3)for(let t=0,a=this.count;t<a;t++)ht.fromBufferAttribute(this,t),ht.applyMatrix3(e),this.setXYZ(t,ht.x,ht.y,ht.z);return this}applyMatrix4(e){for(let t=0,a=this.count;t<a;t++)ht.fromBufferAttribute(this,t),ht.applyMatrix4(e),this.setXYZ(t,ht.x,ht.y,ht.z);return this}applyNormalMatrix(e){for(let t=0,a=this.count;t<a;t++)ht.fromBufferAttribute(this,t),ht.applyNormalMatrix(e),this.setXYZ(t,ht.x,ht.y,ht.z);return this}transformDirection(e){for(let t=0,a=this.count;t<a;t++)ht.fromBufferAttribute(this,t),ht.transformDirection(e),this.setXYZ(t,ht.x,ht.y,ht.z);return this}set(e,t=0){return this.array.set(e,t),this}getComponent(e,t){let a=this.array[e*this.itemSize+t];return this.normalized&&(a=ta(a,this.array)),a}setComponent(e,t,a){return this.normalized&&(a=$e(a,this.array)),this.array[e*this.itemSize+t]=a,this}getX(e){let t=this.array[e*this.itemSize];return this.normalized&&(t=ta(t,this.array)),t}setX(e,t){return this.normalized&&(t=$e(t,this.array)),this.array[e*this.itemSize]=t,this}getY(e){let t=this.array[e*this.itemSize+1];return this.normalized&&(t=ta(t,this.array)),t}setY(e,t){return this.normalized&&(t=$e(t,this.array)),this.array[e*this.itemSize+1]=t,this}getZ(e){let t=this.array[e*this.itemSize+2];return this.normalized&&(t=ta(t,this.array)),t}setZ(e,t){return this.normalized&&(t=$e(t,this.array)),this.array[e*this.itemSize+2]=t,this}getW(e){let t=this.array[e*this.itemSize+3];return this.normalized&&(t=ta(t,this.array)),t}setW(e,t){return this.normalized&&(t=$e(t,this.array)),this.array[e*this.itemSize+3]=t,this}setXY(e,t,a){return e*=this.itemSize,this.normalized&&(t=$e(t,this.array),a=$e(a,this.array)),this.array[e+0]=t,this.array[e+1]=a,this}setXYZ(e,t,a,i){return e*=this.itemSize,this.normalized&&(t=$e(t,this.array),a=$e(a,this.array),i=$e(i,this.array)),this.array[e+0]=t,this.array[e+1]=a,this.array[e+2]=i,this}setXYZW(e,t,a,i,r){return e*=this.itemSize,this.normalized&&(t=$e(t,this.array),a=$e(a,this.array),i=$e(i,this.array),r=$e(r,this.array)),this.array[e+0]=t,this.array[e+1]=a,this.array[e+2]=i,this.array[e+3]=r,this}onUpload(e){return this.onUploadCallback=e,this}clone(){return new this.constructor(this.array,this.itemSize).copy(this)}toJSON(){const e={itemSize:this.itemSize,type:this.array.constructor.name,array:Array.from(this.array),normalized:this.normalized};return this.name!==""&&(e.name=this.name),this.usage!==po&&(e.usage=this.usage),e}}class zo extends Be{constructor(e,t,a){super(new Uint16Array(e),t,a)}}class td extends Be{constructor(e,t,a){super(new Uint32Array(e),t,a)}}class xa extends Be{constructor(e,t,a){super(new Float32Array(e),t,a)}}let Rb=0;const Ht=new ze,as=new Et,_n=new O,jt=new ln,ei=new ln,bt=new O;class pt extends hn{constructor(){super(),this.isBufferGeometry=!0,Object.defineProperty(this,"id",{value:Rb++}),this.uuid=oa(),this.name="",this.type="BufferGeometry",this.index=null,this.indirect=null,this.attributes={},this.morphAttributes={},this.morphTargetsRelative=!1,this.groups=[],this.boundingBox=null,this.boundingSphere=null,this.drawRange={start:0,count:1/0},this.userData={}}getIndex(){return this.index}setIndex(e){return Array.isArray(e)?this.index=new(Jl(e)?td:zo)(e,1):this.index=e,this}setIndirect(e){return this.indirect=e,this}getIndirect(){return this.indirect}getAttribute(e){return this.attributes[e]}setAttribute(e,t){return this.attributes[e]=t,this}deleteAttribute(e){return delete this.attributes[e],this}hasAttribute(e){return this.attributes[e]!==void 0}addGroup(e,t,a=0){this.groups.push({start:e,count:t,materialIndex:a})}clearGroups(){this.groups=[]}setDrawRange(e,t){this.drawRange.start=e,this.drawRange.count=t}applyMatrix4(e){const t=this.attributes.position;t!==void 0&&(t.applyMatrix4(e),t.needsUpdate=!0);const a=this.attributes.normal;if(a!==void 0){const r=new Pe().getNormalMatrix(e);a.applyNormalMatrix(r),a.needsUpdate=!0}const i=this.attributes.tangent;return i!==void 0&&(i.transformDirection(e),i.needsUpdate=!0),this.boundingBox!==null&&this.computeBoundingBox(),this.boundingSphere!==null&&this.computeBoundingSphere(),this}applyQuaternion(e){return Ht.makeRotationFromQuaternion(e),this.applyMatrix4(Ht),this}rotateX(e){return Ht.makeRotationX(e),this.applyMatrix4(Ht),this}rotateY(e){return Ht.makeRotationY(e),this.applyMatrix4(Ht),this}rotateZ(e){return Ht.makeRotationZ(e),this.applyMatrix4(Ht),this}translate(e,t,a){return Ht.makeTranslation(e,t,a),this.applyMatrix4(Ht),this}scale(e,t,a){return Ht.makeScale(e,t,a),this.applyMatrix4(Ht),this}lookAt(e){return as.lookAt(e),as.updateMatrix(),this.applyMatrix4(as.matrix),this}center(){return this.computeBoundingBox(),this.boundingBox.getCenter(_n).negate(),this.translate(_n.x,_n.y,_n.z),this}setFromPoints(e){const t=this.getAttribute("position");if(t===void 0){const a=[];for(let i=0,r=e.length;i<r;i++){const s=e[i];a.push(s.x,s.y,s.z||0)}this.setAttribute("position",new xa(a,3))}else{for(let a=0,i=t.count;a<i;a++){const r=e[a];t.setXYZ(a,r.x,r.y,r.z||0)}e.length>t.count&&console.warn("THREE.BufferGeometry: Buffer size too small for points data. Use .dispose() and create a new geometry."),t.needsUpdate=!0}return this}computeBoundingBox(){this.boundingBox===null&&(this.boundingBox=new ln);const e=this.attributes.position,t=this.morphAttributes.position;if(e&&e.isGLBufferAttribute){console.error("THREE.BufferGeometry.computeBoundingBox(): GLBufferAttribute requires a manual bounding box.",this),this.boundingBox.set(new O(-1/0,-1/0,-1/0),new O(1/0,1/0,1/0));return}if(e!==void 0){if(this.boundingBox.setFromBufferAttribute(e),t)for(let a=0,i=t.length;a<i;a++){const r=t[a];jt.setFromBufferAttribute(r),this.morphTargetsRelative?(bt.addVectors(this.boundingBox.min,jt.min),this.boundingBox.expandByPoint(bt),bt.addVectors(this.boundingBox.max,jt.max),this.boundingBox.expandByPoint(bt)):(this.boundingBox.expandByPoint(jt.min),this.boundingBox.expandByPoint(jt.max))}}else this.boundingBox.makeEmpty();(isNaN(this.boundingBox.min.x)||isNaN(this.boundingBox.min.y)||isNaN(this.boundingBox.min.z))&&console.error('THREE.BufferGeometry.computeBoundingBox(): Computed min/max have NaN values. The "position" attribute is likely to have NaN values.',this)}computeBoundingSphere(){this.boundingSphere===null&&(this.boundingSphere=new dn);const e=this.attributes.position,t=this.morphAttributes.position;if(e&&e.isGLBufferAttribute){console.error("THREE.BufferGeometry.computeBoundingSphere(): GLBufferAttribute requires a manual bounding sphere.",this),this.boundingSphere.set(new O,1/0);return}if(e){const a=this.boundingSphere.center;if(jt.setFromBufferAttribute(e),t)for(let r=0,s=t.length;r<s;r++){const o=t[r];ei.setFromBufferAttribute(o),this.morphTargetsRelative?(bt.addVectors(jt.min,ei.min),jt.expandByPoint(bt),bt.addVectors(jt.max,ei.max),jt.expandByPoint(bt)):(jt.expandByPoint(ei.min),jt.expandByPoint(ei.max))}jt.getCenter(a);let i=0;for(let r=0,s=e.count;r<s;r++)bt.fromBufferAttribute(e,r),i=Math.max(i,a.distanceToSquared(bt));if(t)for(let r=0,s=t.length;r<s;r++){const o=t[r],c=this.morphTargetsRelative;for(let l=0,h=o.count;l<h;l++)bt.fromBufferAttribute(o,l),c&&(_n.fromBufferAttribute(e,l),bt.add(_n)),i=Math.max(i,a.distanceToSquared(bt))}this.boundingSphere.radius=Math.sqrt(i),isNaN(this.boundingSphere.radius)&&console.error('THREE.BufferGeometry.computeBoundingSphere(): Computed radius is NaN. The "position" attribute is likely to have NaN values.',this)}}computeTangents(){const e=this.index,t=this.attributes;if(e===null||t.position===void 0||t.normal===void 0||t.uv===void 0){console.error("THREE.BufferGeometry: .computeTangents() failed. Missing required attributes (index, position, normal or uv)");return}const a=t.position,i=t.normal,r=t.uv;this.hasAttribute("tangent")===!1&&this.setAttribute("tangent",new Be(new Float32Array(4*a.count),4));const s=this.getAttribute("tangent"),o=[],c=[];for(let k=0;k<a.count;k++)o[k]=new O,c[k]=new O;const l=new O,h=new O,d=new O,f=new De,b=new De,p=new De,g=new O,m=new O;function u(k,w,M){l.fromBufferAttribute(a,k),h.fromBufferAttribute(a,w),d.fromBufferAttribute(a,M),f.fromBufferAttribute(r,k),b.fromBufferAttribute(r,w),p.fromBufferAttribute(r,M),h.sub(l),d.sub(l),b.sub(f),p.sub(f);const R=1/(b.x*p.y-p.x*b.y);isFinite(R)&&(g.copy(h).multiplyScalar(p.y).addScaledVector(d,-b.y).multiplyScalar(R),m.copy(d).multiplyScalar(b.x).addScaledVector(h,-p.x).multiplyScalar(R),o[k].add(g),o[w].add(g),o[M].add(g),c[k].add(m),c[w].add(m),c[M].add(m))}let y=this.groups;y.length===0&&(y=[{start:0,count:e.count}]);for(let k=0,w=y.length;k<w;++k){const M=y[k],R=M.start,U=M.count;for(let P=R,D=R+U;P<D;P+=3)u(e.getX(P+0),e.getX(P+1),e.getX(P+2))}const x=new O,v=new O,E=new O,_=new O;function A(k){E.fromBufferAttribute(i,k),_.copy(E);const w=o[k];x.copy(w),x.sub(E.multiplyScalar(E.dot(w))).normalize(),v.crossVectors(_,w);const R=v.dot(c[k])<0?-1:1;s.setXYZW(k,x.x,x.y,x.z,R)}for(let k=0,w=y.length;k<w;++k){const M=y[k],R=M.start,U=M.count;for(let P=R,D=R+U;P<D;P+=3)A(e.getX(P+0)),A(e.getX(P+1)),A(e.getX(P+2))}}computeVertexNormals(){const e=this.index,t=this.getAttribute("position");if(t!==void 0){let a=this.getAttribute("normal");if(a===void 0)a=new Be(new Float32Array(t.count*3),3),this.setAttribute("normal",a);else for(let f=0,b=a.count;f<b;f++)a.setXYZ(f,0,0,0);const i=new O,r=new O,s=new O,o=new O,c=new O,l=new O,h=new O,d=new O;if(e)for(let f=0,b=e.count;f<b;f+=3){const p=e.getX(f+0),g=e.getX(f+1),m=e.getX(f+2);i.fromBufferAttribute(t,p),r.fromBufferAttribute(t,g),s.fromBufferAttribute(t,m),h.subVectors(s,r),d.subVectors(i,r),h.cross(d),o.fromBufferAttribute(a,p),c.fromBufferAttribute(a,g),l.fromBufferAttribute(a,m),o.add(h),c.add(h),l.add(h),a.setXYZ(p,o.x,o.y,o.z),a.setXYZ(g,c.x,c.y,c.z),a.setXYZ(m,l.x,l.y,l.z)}else for(let f=0,b=t.count;f<b;f+=3)i.fromBufferAttribute(t,f+0),r.fromBufferAttribute(t,f+1),s.fromBufferAttribute(t,f+2),h.subVectors(s,r),d.subVectors(i,r),h.cross(d),a.setXYZ(f+0,h.x,h.y,h.z),a.setXYZ(f+1,h.x,h.y,h.z),a.setXYZ(f+2,h.x,h.y,h.z);this.normalizeNormals(),a.needsUpdate=!0}}normalizeNormals(){const e=this.attributes.normal;for(let t=0,a=e.count;t<a;t++)bt.fromBufferAttribute(e,t),bt.normalize(),e.setXYZ(t,bt.x,bt.y,bt.z)}toNonIndexed(){function e(o,c){const l=o.array,h=o.itemSize,d=o.normalized,f=new l.constructor(c.length*h);let b=0,p=0;for(let g=0,m=c.length;g<m;g++){o.isInterleavedBufferAttribute?b=c[g]*o.data.stride+o.offset:b=c[g]*h;for(let u=0;u<h;u++)f[p++]=l[b++]}return new Be(f,h,d)}if(this.index===null)return console.warn("THREE.BufferGeometry.toNonIndexed(): BufferGeometry is already non-indexed."),this;const t=new pt,a=this.index.array,i=this.attributes;for(const o in i){const c=i[o],l=e(c,a);t.setAttribute(o,l)}const r=this.morphAttributes;for(const o in r){const c=[],l=r[o];for(let h=0,d=l.length;h<d;h++){const f=l[h],b=e(f,a);c.push(b)}t.morphAttributes[o]=c}t.morphTargetsRelative=this.morphTargetsRelative;const s=this.groups;for(let o=0,c=s.length;o<c;o++){const l=s[o];t.addGroup(l.start,l.count,l.materialIndex)}return t}toJSON(){const e={metadata:{version:4.6,type:"BufferGeometry",generator:"BufferGeometry.toJSON"}};if(e.uuid=this.uuid,e.type=this.type,this.name!==""&&(e.name=this.name),Object.keys(this.userData).length>0&&(e.userData=this.userData),this.parameters!==void 0){const c=this.parameters;for(const l in c)c[l]!==void 0&&(e[l]=c[l]);return e}e.data={attributes:{}};const t=this.index;t!==null&&(e.data.index={type:t.array.constructor.name,array:Array.prototype.slice.call(t.array)});const a=this.attributes;for(const c in a){const l=a[c];e.data.attributes[c]=l.toJSON(e.data)}const i={};let r=!1;for(const c in this.morphAttributes){const l=this.morphAttributes[c],h=[];for(let d=0,f=l.length;d<f;d++){const b=l[d];h.push(b.toJSON(e.data))}h.length>0&&(i[c]=h,r=!0)}r&&(e.data.morphAttributes=i,e.data.morphTargetsRelative=this.morphTargetsRelative);const s=this.groups;s.length>0&&(e.data.groups=JSON.parse(JSON.stringify(s)));const o=this.boundingSphere;return o!==null&&(e.data.boundingSphere={center:o.center.toArray(),radius:o.radius}),e}clone(){return new this.constructor().copy(this)}copy(e){this.index=null,this.attributes={},this.morphAttributes={},this.groups=[],this.boundingBox=null,this.boundingSphere=null;const t={};this.name=e.name;const a=e.index;a!==null&&this.setIndex(a.clone(t));const i=e.attributes;for(const l in i){const h=i[l];this.setAttribute(l,h.clone(t))}const r=e.morphAttributes;for(const l in r){const h=[],d=r[l];for(let f=0,b=d.length;f<b;f++)h.push(d[f].clone(t));this.morphAttributes[l]=h}this.morphTargetsRelative=e.morphTargetsRelative;const s=e.groups;for(let l=0,h=s.length;l<h;l++){const d=s[l];this.addGroup(d.start,d.count,d.materialIndex)}const o=e.boundingBox;o!==null&&(this.boundingBox=o.clone());const c=e.boundingSphere;return c!==null&&(this.boundingSphere=c.clone()),this.drawRange.start=e.drawRange.start,this.drawRange.count=e.drawRange.count,this.userData=e.userData,this}dispose(){this.dispatchEvent({type:"dispose"})}}const Hc=new ze,Ja=new Ai,zi=new dn,Vc=new O,Bi=new O,Gi=new O,Hi=new O,ns=new O,Vi=new O,Wc=new O,Wi=new O;class Nt extends Et{constructor(e=new pt,t=new ed){super(),this.isMesh=!0,this.type="Mesh",this.geometry=e,this.material=t,this.updateMorphTargets()}copy(e,t){return super.copy(e,t),e.morphTargetInfluences!==void 0&&(this.morphTargetInfluences=e.morphTargetInfluences.slice()),e.morphTargetDictionary!==void 0&&(this.morphTargetDictionary=Object.assign({},e.morphTargetDictionary)),this.material=Array.isArray(e.material)?e.material.slice():e.material,this.geometry=e.geometry,this}updateMorphTargets(){const t=this.geometry.morphAttributes,a=Object.keys(t);if(a.length>0){const i=t[a[0]];if(i!==void 0){this.morphTargetInfluences=[],this.morphTargetDictionary={};for(let r=0,s=i.length;r<s;r++){const o=i[r].name||String(r);this.morphTargetInfluences.push(0),this.morphTargetDictionary[o]=r}}}}getVertexPosition(e,t){const a=this.geometry,i=a.attributes.position,r=a.morphAttributes.position,s=a.morphTargetsRelative;t.fromBufferAttribute(i,e);const o=this.morphTargetInfluences;if(r&&o){Vi.set(0,0,0);for(let c=0,l=r.length;c<l;c++){const h=o[c],d=r[c];h!==0&&(ns.fromBufferAttribute(d,e),s?Vi.addScaledVector(ns,h):Vi.addScaledVector(ns.sub(t),h))}t.add(Vi)}return t}raycast(e,t){const a=this.geometry,i=this.material,r=this.matrixWorld;i!==void 0&&(a.boundingSphere===null&&a.computeBoundingSphere(),zi.copy(a.boundingSphere),zi.applyMatrix4(r),Ja.copy(e.ray).recast(e.near),!(zi.containsPoint(Ja.origin)===!1&&(Ja.intersectSphere(zi,Vc)===null||Ja.origin.distanceToSquared(Vc)>(e.far-e.near)**2))&&(Hc.copy(r).invert(),Ja.copy(e.ray).applyMatrix4(Hc),!(a.boundingBox!==null&&Ja.intersectsBox(a.boundingBox)===!1)&&this._computeIntersections(e,t,Ja)))}_computeIntersections(e,t,a){let i;const r=this.geometry,s=this.material,o=r.index,c=r.attributes.position,l=r.attributes.uv,h=r.attributes.uv1,d=r.attributes.normal,f=r.groups,b=r.drawRange;if(o!==null)if(Array.isArray(s))for(let p=0,g=f.length;p<g;p++){const m=f[p],u=s[m.materialIndex],y=Math.max(m.start,b.start),x=Math.min(o.count,Math.min(m.start+m.count,b.start+b.count));for(let v=y,E=x;v<E;v+=3){const _=o.getX(v),A=o.getX(v+1),k=o.getX(v+2);i=qi(this,u,e,a,l,h,d,_,A,k),i&&(i.faceIndex=Math.floor(v/3),i.face.materialIndex=m.materialIndex,t.push(i))}}else{const p=Math.max(0,b.start),g=Math.min(o.count,b.start+b.count);for(let m=p,u=g;m<u;m+=3){const y=o.getX(m),x=o.getX(m+1),v=o.getX(m+2);i=qi(this,s,e,a,l,h,d,y,x,v),i&&(i.faceIndex=Math.floor(m/3),t.push(i))}}else if(c!==void 0)if(Array.isArray(s))for(let p=0,g=f.length;p<g;p++){const m=f[p],u=s[m.materialIndex],y=Math.max(m.start,b.start),x=Math.min(c.count,Math.min(m.start+m.count,b.start+b.count));for(let v=y,E=x;v<E;v+=3){const _=v,A=v+1,k=v+2;i=qi(this,u,e,a,l,h,d,_,A,k),i&&(i.faceIndex=Math.floor(v/3),i.face.materialIndex=m.materialIndex,t.push(i))}}else{const p=Math.max(0,b.start),g=Math.min(c.count,b.start+b.count);for(let m=p,u=g;m<u;m+=3){const y=m,x=m+1,v=m+2;i=qi(this,s,e,a,l,h,d,y,x,v),i&&(i.faceIndex=Math.floor(m/3),t.push(i))}}}}function Cb(n,e,t,a,i,r,s,o){let c;if(e.side===Ut?c=a.intersectTriangle(s,r,i,!0,o):c=a.intersectTriangle(i,r,s,e.side===Ma,o),c===null)return null;Wi.copy(o),Wi.applyMatrix4(n.matrixWorld);const l=t.ray.origin.distanceTo(Wi);return l<t.near||l>t.far?null:{distance:l,point:Wi.clone(),object:n}}function qi(n,e,t,a,i,r,s,o,c,l){n.getVertexPosition(o,Bi),n.getVertexPosition(c,Gi),n.getVertexPosition(l,Hi);const h=Cb(n,e,t,a,Bi,Gi,Hi,Wc);if(h){const d=new O;aa.getBarycoord(Wc,Bi,Gi,Hi,d),i&&(h.uv=aa.getInterpolatedAttribute(i,o,c,l,d,new De)),r&&(h.uv1=aa.getInterpolatedAttribute(r,o,c,l,d,new De)),s&&(h.normal=aa.getInterpolatedAttribute(s,o,c,l,d,new O),h.normal.dot(a.direction)>0&&h.normal.multiplyScalar(-1));const f={a:o,b:c,c:l,normal:new O,materialIndex:0};aa.getNormal(Bi,Gi,Hi,f.normal),h.face=f,h.barycoord=d}return h}class Ti extends pt{constructor(e=1,t=1,a=1,i=1,r=1,s=1){super(),this.type="BoxGeometry",this.parameters={width:e,height:t,depth:a,widthSegments:i,heightSegments:r,depthSegments:s};const o=this;i=Math.floor(i),r=Math.floor(r),s=Math.floor(s);const c=[],l=[],h=[],d=[];let f=0,b=0;p("z","y","x",-1,-1,a,t,e,s,r,0),p("z","y","x",1,-1,a,t,-e,s,r,1),p("x","z","y",1,1,e,a,t,i,s,2),p("x","z","y",1,-1,e,a,-t,i,s,3),p("x","y","z",1,-1,e,t,a,i,r,4),p("x","y","z",-1,-1,e,t,-a,i,r,5),this.setIndex(c),this.setAttribute("position",new xa(l,3)),this.setAttribute("normal",new xa(h,3)),this.setAttribute("uv",new xa(d,2));function p(g,m,u,y,x,v,E,_,A,k,w){const M=v/A,R=E/k,U=v/2,P=E/2,D=_/2,V=A+1,B=k+1;let G=0,z=0;const Y=new O;for(let te=0;te<B;te++){const ie=te*R-P;for(let pe=0;pe<V;pe++){const Te=pe*M-U;Y[g]=Te*y,Y[m]=ie*x,Y[u]=D,l.push(Y.x,Y.y,Y.z),Y[g]=0,Y[m]=0,Y[u]=_>0?1:-1,h.push(Y.x,Y.y,Y.z),d.push(pe/A),d.push(1-te/k),G+=1}}for(let te=0;te<k;te++)for(let ie=0;ie<A;ie++){const pe=f+ie+V*te,Te=f+ie+V*(te+1),W=f+(ie+1)+V*(te+1),J=f+(ie+1)+V*te;c.push(pe,Te,J),c.push(Te,W,J),z+=6}o.addGroup(b,z,w),b+=z,f+=G}}copy(e){return super.copy(e),this.parameters=Object.assign({},e.parameters),this}static fromJSON(e){return new Ti(e.width,e.height,e.depth,e.widthSegments,e.heightSegments,e.depthSegments)}}function zn(n){const e={};for(const t in n){e[t]={};for(const a in n[t]){const i=n[t][a];i&&(i.isColor||i.isMatrix3||i.isMatrix4||i.isVector2||i.isVector3||i.isVector4||i.isTexture||i.isQuaternion)?i.isRenderTargetTexture?(console.warn("UniformsUtils: Textures of render targets cannot be cloned via cloneUniforms() or mergeUniforms()."),e[t][a]=null):e[t][a]=i.clone():Array.isArray(i)?e[t][a]=i.slice():e[t][a]=i}}return e}function Tt(n){const e={};for(let t=0;t<n.length;t++){const a=zn(n[t]);for(const i in a)e[i]=a[i]}return e}function Ib(n){const e=[];for(let t=0;t<n.length;t++)e.push(n[t].clone());return e}function ad(n){const e=n.getRenderTarget();return e===null?n.outputColorSpace:e.isXRRenderTarget===!0?e.texture.colorSpace:qe.workingColorSpace}const Pb={clone:zn,merge:Tt};var Db=`void main() {
	gl_Position = projectionMatrix * modelViewMatrix * vec4( position, 1.0 );
}`,Nb=`void main() {
	gl_FragColor = vec4( 1.0, 0.0, 0.0, 1.0 );
}`;class Jt extends Vn{static get type(){return"ShaderMaterial"}constructor(e){super(),this.isShaderMaterial=!0,this.defines={},this.uniforms={},this.uniformsGroups=[],this.vertexShader=Db,this.fragmentShader=Nb,this.linewidth=1,this.wireframe=!1,this.wireframeLinewidth=1,this.fog=!1,this.lights=!1,this.clipping=!1,this.forceSinglePass=!0,this.extensions={clipCullDistance:!1,multiDraw:!1},this.defaultAttributeValues={color:[1,1,1],uv:[0,0],uv1:[0,0]},this.index0AttributeName=void 0,this.uniformsNeedUpdate=!1,this.glslVersion=null,e!==void 0&&this.setValues(e)}copy(e){return super.copy(e),this.fragmentShader=e.fragmentShader,this.vertexShader=e.vertexShader,this.uniforms=zn(e.uniforms),this.uniformsGroups=Ib(e.uniformsGroups),this.defines=Object.assign({},e.defines),this.wireframe=e.wireframe,this.wireframeLinewidth=e.wireframeLinewidth,this.fog=e.fog,this.lights=e.lights,this.clipping=e.clipping,this.extensions=Object.assign({},e.extensions),this.glslVersion=e.glslVersion,this}toJSON(e){const t=super.toJSON(e);t.glslVersion=this.glslVersion,t.uniforms={};for(const i in this.uniforms){const s=this.uniforms[i].value;s&&s.isTexture?t.uniforms[i]={type:"t",value:s.toJSON(e).uuid}:s&&s.isColor?t.uniforms[i]={type:"c",value:s.getHex()}:s&&s.isVector2?t.uniforms[i]={type:"v2",value:s.toArray()}:s&&s.isVector3?t.uniforms[i]={type:"v3",value:s.toArray()}:s&&s.isVector4?t.uniforms[i]={type:"v4",value:s.toArray()}:s&&s.isMatrix3?t.uniforms[i]={type:"m3",value:s.toArray()}:s&&s.isMatrix4?t.uniforms[i]={type:"m4",value:s.toArray()}:t.uniforms[i]={value:s}}Object.keys(this.defines).length>0&&(t.defines=this.defines),t.vertexShader=this.vertexShader,t.fragmentShader=this.fragmentShader,t.lights=this.lights,t.clipping=this.clipping;const a={};for(const i in this.extensions)this.extensions[i]===!0&&(a[i]=!0);return Object.keys(a).length>0&&(t.extensions=a),t}}class nd extends Et{constructor(){super(),this.isCamera=!0,this.type="Camera",this.matrixWorldInverse=new ze,this.projectionMatrix=new ze,this.projectionMatrixInverse=new ze,this.coordinateSystem=va}copy(e,t){return super.copy(e,t),this.matrixWorldInverse.copy(e.matrixWorldInverse),this.projectionMatrix.copy(e.projectionMatrix),this.projectionMatrixInverse.copy(e.projectionMatrixInverse),this.coordinateSystem=e.coordinateSystem,this}getWorldDirection(e){return super.getWorldDirection(e).negate()}updateMatrixWorld(e){super.updateMatrixWorld(e),this.matrixWorldInverse.copy(this.matrixWorld).invert()}updateWorldMatrix(e,t){super.updateWorldMatrix(e,t),this.matrixWorldInverse.copy(this.matrixWorld).invert()}clone(){return new this.constructor().copy(this)}}const Fa=new O,qc=new De,Xc=new De;class Pt extends nd{constructor(e=50,t=1,a=.1,i=2e3){super(),this.isPerspectiveCamera=!0,this.type="PerspectiveCamera",this.fov=e,this.zoom=1,this.near=a,this.far=i,this.focus=10,this.aspect=t,this.view=null,this.filmGauge=35,this.filmOffset=0,this.updateProjectionMatrix()}copy(e,t){return super.copy(e,t),this.fov=e.fov,this.zoom=e.zoom,this.near=e.near,this.far=e.far,this.focus=e.focus,this.aspect=e.aspect,this.view=e.view===null?null:Object.assign({},e.view),this.filmGauge=e.filmGauge,this.filmOffset=e.filmOffset,this}setFocalLength(e){const t=.5*this.getFilmHeight()/e;this.fov=yi*2*Math.atan(t),this.updateProjectionMatrix()}getFocalLength(){const e=Math.tan(bi*.5*this.fov);return .5*this.getFilmHeight()/e}getEffectiveFOV(){return yi*2*Math.atan(Math.tan(bi*.5*this.fov)/this.zoom)}getFilmWidth(){return this.filmGauge*Math.min(this.aspect,1)}getFilmHeight(){return this.filmGauge/Math.max(this.aspect,1)}getViewBounds(e,t,a){Fa.set(-1,-1,.5).applyMatrix4(this.projectionMatrixInverse),t.set(Fa.x,Fa.y).multiplyScalar(-e/Fa.z),Fa.set(1,1,.5).applyMatrix4(this.projectionMatrixInverse),a.set(Fa.x,Fa.y).multiplyScalar(-e/Fa.z)}getViewSize(e,t){return this.getViewBounds(e,qc,Xc),t.subVectors(Xc,qc)}setViewOffset(e,t,a,i,r,s){this.aspect=e/t,this.view===null&&(this.view={enabled:!0,fullWidth:1,fullHeight:1,offsetX:0,offsetY:0,width:1,height:1}),this.view.enabled=!0,this.view.fullWidth=e,this.view.fullHeight=t,this.view.offsetX=a,this.view.offsetY=i,this.view.width=r,this.view.height=s,this.updateProjectionMatrix()}clearViewOffset(){this.view!==null&&(this.view.enabled=!1),this.updateProjectionMatrix()}updateProjectionMatrix(){const e=this.near;let t=e*Math.tan(bi*.5*this.fov)/this.zoom,a=2*t,i=this.aspect*a,r=-.5*i;const s=this.view;if(this.view!==null&&this.view.enabled){const c=s.fullWidth,l=s.fullHeight;r+=s.offsetX*i/c,t-=s.offsetY*a/l,i*=s.width/c,a*=s.height/l}const o=this.filmOffset;o!==0&&(r+=e*o/this.getFilmWidth()),this.projectionMatrix.makePerspective(r,r+i,t,t-a,e,this.far,this.coordinateSystem),this.projectionMatrixInverse.copy(this.projectionMatrix).invert()}toJSON(e){const t=super.toJSON(e);return t.object.fov=this.fov,t.object.zoom=this.zoom,t.object.near=this.near,t.object.far=this.far,t.object.focus=this.focus,t.object.aspect=this.aspect,this.view!==null&&(t.object.view=Object.assign({},this.view)),t.object.filmGauge=this.filmGauge,t.object.filmOffset=this.filmOffset,t}}const En=-90,Sn=1;class Ub extends Et{constructor(e,t,a){super(),this.type="CubeCamera",this.renderTarget=a,this.coordinateSystem=null,this.activeMipmapLevel=0;const i=new Pt(En,Sn,e,t);i.layers=this.layers,this.add(i);const r=new Pt(En,Sn,e,t);r.layers=this.layers,this.add(r);const s=new Pt(En,Sn,e,t);s.layers=this.layers,this.add(s);const o=new Pt(En,Sn,e,t);o.layers=this.layers,this.add(o);const c=new Pt(En,Sn,e,t);c.layers=this.layers,this.add(c);const l=new Pt(En,Sn,e,t);l.layers=this.layers,this.add(l)}updateCoordinateSystem(){const e=this.coordinateSystem,t=this.children.concat(),[a,i,r,s,o,c]=t;for(const l of t)this.remove(l);if(e===va)a.up.set(0,1,0),a.lookAt(1,0,0),i.up.set(0,1,0),i.lookAt(-1,0,0),r.up.set(0,0,-1),r.lookAt(0,1,0),s.up.set(0,0,1),s.lookAt(0,-1,0),o.up.set(0,1,0),o.lookAt(0,0,1),c.up.set(0,1,0),c.lookAt(0,0,-1);else if(e===vr)a.up.set(0,-1,0),a.lookAt(-1,0,0),i.up.set(0,-1,0),i.lookAt(1,0,0),r.up.set(0,0,1),r.lookAt(0,1,0),s.up.set(0,0,-1),s.lookAt(0,-1,0),o.up.set(0,-1,0),o.lookAt(0,0,1),c.up.set(0,-1,0),c.lookAt(0,0,-1);else throw new Error("THREE.CubeCamera.updateCoordinateSystem(): Invalid coordinate system: "+e);for(const l of t)this.add(l),l.updateMatrixWorld()}update(e,t){this.parent===null&&this.updateMatrixWorld();const{renderTarget:a,activeMipmapLevel:i}=this;this.coordinateSystem!==e.coordinateSystem&&(this.coordinateSystem=e.coordinateSystem,this.updateCoordinateSystem());const[r,s,o,c,l,h]=this.children,d=e.getRenderTarget(),f=e.getActiveCubeFace(),b=e.getActiveMipmapLevel(),p=e.xr.enabled;e.xr.enabled=!1;const g=a.texture.generateMipmaps;a.texture.generateMipmaps=!1,e.setRenderTarget(a,0,i),e.render(t,r),e.setRenderTarget(a,1,i),e.render(t,s),e.setRenderTarget(a,2,i),e.render(t,o),e.setRenderTarget(a,3,i),e.render(t,c),e.setRenderTarget(a,4,i),e.render(t,l),a.texture.generateMipmaps=g,e.setRenderTarget(a,5,i),e.render(t,h),e.setRenderTarget(d,f,b),e.xr.enabled=p,a.texture.needsPMREMUpdate=!0}}class id extends _t{constructor(e,t,a,i,r,s,o,c,l,h){e=e!==void 0?e:[],t=t!==void 0?t:Fn,super(e,t,a,i,r,s,o,c,l,h),this.isCubeTexture=!0,this.flipY=!1}get images(){return this.image}set images(e){this.image=e}}class Fb extends Sa{constructor(e=1,t={}){super(e,e,t),this.isWebGLCubeRenderTarget=!0;const a={width:e,height:e,depth:1},i=[a,a,a,a,a,a];this.texture=new id(i,t.mapping,t.wrapS,t.wrapT,t.magFilter,t.minFilter,t.format,t.type,t.anisotropy,t.colorSpace),this.texture.isRenderTargetTexture=!0,this.texture.generateMipmaps=t.generateMipmaps!==void 0?t.generateMipmaps:!1,this.texture.minFilter=t.minFilter!==void 0?t.minFilter:na}fromEquirectangularTexture(e,t){this.texture.type=t.type,this.texture.colorSpace=t.colorSpace,this.texture.generateMipmaps=t.generateMipmaps,this.texture.minFilter=t.minFilter,this.texture.magFilter=t.magFilter;const a={uniforms:{tEquirect:{value:null}},vertexShader:`

				varying vec3 vWorldDirection;

				vec3 transformDirection( in vec3 dir, in mat4 matrix ) {

					return normalize( ( matrix * vec4( dir, 0.0 ) ).xyz );

				}

				void main() {

					vWorldDirection = transformDirection( position, modelMatrix );

					#include <begin_vertex>
					#include <project_vertex>

				}
			`,fragmentShader:`

				uniform sampler2D tEquirect;

				varying vec3 vWorldDirection;

				#include <common>

				void main() {

					vec3 direction = normalize( vWorldDirection );

					vec2 sampleUV = equirectUv( direction );

					gl_FragColor = texture2D( tEquirect, sampleUV );

				}
			`},i=new Ti(5,5,5),r=new Jt({name:"CubemapFromEquirect",uniforms:zn(a.uniforms),vertexShader:a.vertexShader,fragmentShader:a.fragmentShader,side:Ut,blending:Ga});r.uniforms.tEquirect.value=t;const s=new Nt(i,r),o=t.minFilter;return t.minFilter===Ba&&(t.minFilter=na),new Ub(1,10,this).update(e,s),t.minFilter=o,s.geometry.dispose(),s.material.dispose(),this}clear(e,t,a,i){const r=e.getRenderTarget();for(let s=0;s<6;s++)e.setRenderTarget(this,s),e.clear(t,a,i);e.setRenderTarget(r)}}const is=new O,Lb=new O,jb=new Pe;class ja{constructor(e=new O(1,0,0),t=0){this.isPlane=!0,this.normal=e,this.constant=t}set(e,t){return this.normal.copy(e),this.constant=t,this}setComponents(e,t,a,i){return this.normal.set(e,t,a),this.constant=i,this}setFromNormalAndCoplanarPoint(e,t){return this.normal.copy(e),this.constant=-t.dot(this.normal),this}setFromCoplanarPoints(e,t,a){const i=is.subVectors(a,t).cross(Lb.subVectors(e,t)).normalize();return this.setFromNormalAndCoplanarPoint(i,e),this}copy(e){return this.normal.copy(e.normal),this.constant=e.constant,this}normalize(){const e=1/this.normal.length();return this.normal.multiplyScalar(e),this.constant*=e,this}negate(){return this.constant*=-1,this.normal.negate(),this}distanceToPoint(e){return this.normal.dot(e)+this.constant}distanceToSphere(e){return this.distanceToPoint(e.center)-e.radius}projectPoint(e,t){return t.copy(e).addScaledVector(this.normal,-this.distanceToPoint(e))}intersectLine(e,t){const a=e.delta(is),i=this.normal.dot(a);if(i===0)return this.distanceToPoint(e.start)===0?t.copy(e.start):null;const r=-(e.start.dot(this.normal)+this.constant)/i;return r<0||r>1?null:t.copy(e.start).addScaledVector(a,r)}intersectsLine(e){const t=this.distanceToPoint(e.start),a=this.distanceToPoint(e.end);return t<0&&a>0||a<0&&t>0}intersectsBox(e){return e.intersectsPlane(this)}intersectsSphere(e){return e.intersectsPlane(this)}coplanarPoint(e){return e.copy(this.normal).multiplyScalar(-this.constant)}applyMatrix4(e,t){const a=t||jb.getNormalMatrix(e),i=this.coplanarPoint(is).applyMatrix4(e),r=this.normal.applyMatrix3(a).normalize();return this.constant=-i.dot(r),this}translate(e){return this.constant-=e.dot(this.normal),this}equals(e){return e.normal.equals(this.normal)&&e.constant===this.constant}clone(){return new this.constructor().copy(this)}}const Ya=new dn,Xi=new O;class rd{constructor(e=new ja,t=new ja,a=new ja,i=new ja,r=new ja,s=new ja){this.planes=[e,t,a,i,r,s]}set(e,t,a,i,r,s){const o=this.planes;return o[0].copy(e),o[1].copy(t),o[2].copy(a),o[3].copy(i),o[4].copy(r),o[5].copy(s),this}copy(e){const t=this.planes;for(let a=0;a<6;a++)t[a].copy(e.planes[a]);return this}setFromProjectionMatrix(e,t=va){const a=this.planes,i=e.elements,r=i[0],s=i[1],o=i[2],c=i[3],l=i[4],h=i[5],d=i[6],f=i[7],b=i[8],p=i[9],g=i[10],m=i[11],u=i[12],y=i[13],x=i[14],v=i[15];if(a[0].setComponents(c-r,f-l,m-b,v-u).normalize(),a[1].setComponents(c+r,f+l,m+b,v+u).normalize(),a[2].setComponents(c+s,f+h,m+p,v+y).normalize(),a[3].setComponents(c-s,f-h,m-p,v-y).normalize(),a[4].setComponents(c-o,f-d,m-g,v-x).normalize(),t===va)a[5].setComponents(c+o,f+d,m+g,v+x).normalize();else if(t===vr)a[5].setComponents(o,d,g,x).normalize();else throw new Error("THREE.Frustum.setFromProjectionMatrix(): Invalid coordinate system: "+t);return this}intersectsObject(e){if(e.boundingSphere!==void 0)e.boundingSphere===null&&e.computeBoundingSphere(),Ya.copy(e.boundingSphere).applyMatrix4(e.matrixWorld);else{const t=e.geometry;t.boundingSphere===null&&t.computeBoundingSphere(),Ya.copy(t.boundingSphere).applyMatrix4(e.matrixWorld)}return this.intersectsSphere(Ya)}intersectsSprite(e){return Ya.center.set(0,0,0),Ya.radius=.7071067811865476,Ya.applyMatrix4(e.matrixWorld),this.intersectsSphere(Ya)}intersectsSphere(e){const t=this.planes,a=e.center,i=-e.radius;for(let r=0;r<6;r++)if(t[r].distanceToPoint(a)<i)return!1;return!0}intersectsBox(e){const t=this.planes;for(let a=0;a<6;a++){const i=t[a];if(Xi.x=i.normal.x>0?e.max.x:e.min.x,Xi.y=i.normal.y>0?e.max.y:e.min.y,Xi.z=i.normal.z>0?e.max.z:e.min.z,i.distanceToPoint(Xi)<0)return!1}return!0}containsPoint(e){const t=this.planes;for(let a=0;a<6;a++)if(t[a].distanceToPoint(e)<0)return!1;return!0}clone(){return new this.constructor().copy(this)}}function sd(){let n=null,e=!1,t=null,a=null;function i(r,s){t(r,s),a=n.requestAnimationFrame(i)}return{start:function(){e!==!0&&t!==null&&(a=n.requestAnimationFrame(i),e=!0)},stop:function(){n.cancelAnimationFrame(a),e=!1},setAnimationLoop:function(r){t=r},setContext:function(r){n=r}}}function Ob(n){const e=new WeakMap;function t(o,c){const l=o.array,h=o.usage,d=l.byteLength,f=n.createBuffer();n.bindBuffer(c,f),n.bufferData(c,l,h),o.onUploadCallback();let b;if(l instanceof Float32Array)b=n.FLOAT;else if(l instanceof Uint16Array)o.isFloat16BufferAttribute?b=n.HALF_FLOAT:b=n.UNSIGNED_SHORT;else if(l instanceof Int16Array)b=n.SHORT;else if(l instanceof Uint32Array)b=n.UNSIGNED_INT;else if(l instanceof Int32Array)b=n.INT;else if(l instanceof Int8Array)b=n.BYTE;else if(l instanceof Uint8Array)b=n.UNSIGNED_BYTE;else if(l instanceof Uint8ClampedArray)b=n.UNSIGNED_BYTE;else throw new Error("THREE.WebGLAttributes: Unsupported buffer data format: "+l);return{buffer:f,type:b,bytesPerElement:l.BYTES_PER_ELEMENT,version:o.version,size:d}}function a(o,c,l){const h=c.array,d=c.updateRanges;if(n.bindBuffer(l,o),d.length===0)n.bufferSubData(l,0,h);else{d.sort((b,p)=>b.start-p.start);let f=0;for(let b=1;b<d.length;b++){const p=d[f],g=d[b];g.start<=p.start+p.count+1?p.count=Math.max(p.count,g.start+g.count-p.start):(++f,d[f]=g)}d.length=f+1;for(let b=0,p=d.length;b<p;b++){const g=d[b];n.bufferSubData(l,g.start*h.BYTES_PER_ELEMENT,h,g.start,g.count)}c.clearUpdateRanges()}c.onUploadCallback()}function i(o){return o.isInterleavedBufferAttribute&&(o=o.data),e.get(o)}function r(o){o.isInterleavedBufferAttribute&&(o=o.data);const c=e.get(o);c&&(n.deleteBuffer(c.buffer),e.delete(o))}function s(o,c){if(o.isInterleavedBufferAttribute&&(o=o.data),o.isGLBufferAttribute){const h=e.get(o);(!h||h.version<o.version)&&e.set(o,{buffer:o.buffer,type:o.type,bytesPerElement:o.elementSize,version:o.version});return}const l=e.get(o);if(l===void 0)e.set(o,t(o,c));else if(l.version<o.version){if(l.size!==o.array.byteLength)throw new Error("THREE.WebGLAttributes: The size of the buffer attribute's array buffer does not match the original size. Resizing buffer attributes is not supported.");a(l.buffer,o,c),l.version=o.version}}return{get:i,remove:r,update:s}}class Bn extends pt{constructor(e=1,t=1,a=1,i=1){super(),this.type="PlaneGeometry",this.parameters={width:e,height:t,widthSegments:a,heightSegments:i};const r=e/2,s=t/2,o=Math.floor(a),c=Math.floor(i),l=o+1,h=c+1,d=e/o,f=t/c,b=[],p=[],g=[],m=[];for(let u=0;u<h;u++){const y=u*f-s;for(let x=0;x<l;x++){const v=x*d-r;p.push(v,-y,0),g.push(0,0,1),m.push(x/o),m.push(1-u/c)}}for(let u=0;u<c;u++)for(let y=0;y<o;y++){const x=y+l*u,v=y+l*(u+1),E=y+1+l*(u+1),_=y+1+l*u;b.push(x,v,_),b.push(v,E,_)}this.setIndex(b),this.setAttribute("position",new xa(p,3)),this.setAttribute("normal",new xa(g,3)),this.setAttribute("uv",new xa(m,2))}copy(e){return super.copy(e),this.parameters=Object.assign({},e.parameters),this}static fromJSON(e){return new Bn(e.width,e.height,e.widthSegments,e.heightSegments)}}var zb=`#ifdef USE_ALPHAHASH
	if ( diffuseColor.a < getAlphaHashThreshold( vPosition ) ) discard;
#endif`,Bb=`#ifdef USE_ALPHAHASH
	const float ALPHA_HASH_SCALE = 0.05;
	float hash2D( vec2 value ) {
		return fract( 1.0e4 * sin( 17.0 * value.x + 0.1 * value.y ) * ( 0.1 + abs( sin( 13.0 * value.y + value.x ) ) ) );
	}
	float hash3D( vec3 value ) {
		return hash2D( vec2( hash2D( value.xy ), value.z ) );
	}
	float getAlphaHashThreshold( vec3 position ) {
		float maxDeriv = max(
			length( dFdx( position.xyz ) ),
			length( dFdy( position.xyz ) )
		);
		float pixScale = 1.0 / ( ALPHA_HASH_SCALE * maxDeriv );
		vec2 pixScales = vec2(
			exp2( floor( log2( pixScale ) ) ),
			exp2( ceil( log2( pixScale ) ) )
		);
		vec2 alpha = vec2(
			hash3D( floor( pixScales.x * position.xyz ) ),
			hash3D( floor( pixScales.y * position.xyz ) )
		);
		float lerpFactor = fract( log2( pixScale ) );
		float x = ( 1.0 - lerpFactor ) * alpha.x + lerpFactor * alpha.y;
		float a = min( lerpFactor, 1.0 - lerpFactor );
		vec3 cases = vec3(
			x * x / ( 2.0 * a * ( 1.0 - a ) ),
			( x - 0.5 * a ) / ( 1.0 - a ),
			1.0 - ( ( 1.0 - x ) * ( 1.0 - x ) / ( 2.0 * a * ( 1.0 - a ) ) )
		);
		float threshold = ( x < ( 1.0 - a ) )
			? ( ( x < a ) ? cases.x : cases.y )
			: cases.z;
		return clamp( threshold , 1.0e-6, 1.0 );
	}
#endif`,Gb=`#ifdef USE_ALPHAMAP
	diffuseColor.a *= texture2D( alphaMap, vAlphaMapUv ).g;
#endif`,Hb=`#ifdef USE_ALPHAMAP
	uniform sampler2D alphaMap;
#endif`,Vb=`#ifdef USE_ALPHATEST
	#ifdef ALPHA_TO_COVERAGE
	diffuseColor.a = smoothstep( alphaTest, alphaTest + fwidth( diffuseColor.a ), diffuseColor.a );
	if ( diffuseColor.a == 0.0 ) discard;
	#else
	if ( diffuseColor.a < alphaTest ) discard;
	#endif
#endif`,Wb=`#ifdef USE_ALPHATEST
	uniform float alphaTest;
#endif`,qb=`#ifdef USE_AOMAP
	float ambientOcclusion = ( texture2D( aoMap, vAoMapUv ).r - 1.0 ) * aoMapIntensity + 1.0;
	reflectedLight.indirectDiffuse *= ambientOcclusion;
	#if defined( USE_CLEARCOAT ) 
		clearcoatSpecularIndirect *= ambientOcclusion;
	#endif
	#if defined( USE_SHEEN ) 
		sheenSpecularIndirect *= ambientOcclusion;
	#endif
	#if defined( USE_ENVMAP ) && defined( STANDARD )
		float dotNV = saturate( dot( geometryNormal, geometryViewDir ) );
		reflectedLight.indirectSpecular *= computeSpecularOcclusion( dotNV, ambientOcclusion, material.roughness );
	#endif
#endif`,Xb=`#ifdef USE_AOMAP
	uniform sampler2D aoMap;
	uniform float aoMapIntensity;
#endif`,Kb=`#ifdef USE_BATCHING
	#if ! defined( GL_ANGLE_multi_draw )
	#define gl_DrawID _gl_DrawID
	uniform int _gl_DrawID;
	#endif
	uniform highp sampler2D batchingTexture;
	uniform highp usampler2D batchingIdTexture;
	mat4 getBatchingMatrix( const in float i ) {
		int size = textureSize( batchingTexture, 0 ).x;
		int j = int( i ) * 4;
		int x = j % size;
		int y = j / size;
		vec4 v1 = texelFetch( batchingTexture, ivec2( x, y ), 0 );
		vec4 v2 = texelFetch( batchingTexture, ivec2( x + 1, y ), 0 );
		vec4 v3 = texelFetch( batchingTexture, ivec2( x + 2, y ), 0 );
		vec4 v4 = texelFetch( batchingTexture, ivec2( x + 3, y ), 0 );
		return mat4( v1, v2, v3, v4 );
	}
	float getIndirectIndex( const in int i ) {
		int size = textureSize( batchingIdTexture, 0 ).x;
		int x = i % size;
		int y = i / size;
		return float( texelFetch( batchingIdTexture, ivec2( x, y ), 0 ).r );
	}
#endif
#ifdef USE_BATCHING_COLOR
	uniform sampler2D batchingColorTexture;
	vec3 getBatchingColor( const in float i ) {
		int size = textureSize( batchingColorTexture, 0 ).x;
		int j = int( i );
		int x = j % size;
		int y = j / size;
		return texelFetch( batchingColorTexture, ivec2( x, y ), 0 ).rgb;
	}
#endif`,Jb=`#ifdef USE_BATCHING
	mat4 batchingMatrix = getBatchingMatrix( getIndirectIndex( gl_DrawID ) );
#endif`,Yb=`vec3 transformed = vec3( position );
#ifdef USE_ALPHAHASH
	vPosition = vec3( position );
#endif`,Zb=`vec3 objectNormal = vec3( normal );
#ifdef USE_TANGENT
	vec3 objectTangent = vec3( tangent.xyz );
#endif`,Qb=`float G_BlinnPhong_Implicit( ) {
	return 0.25;
}
float D_BlinnPhong( const in float shininess, const in float dotNH ) {
	return RECIPROCAL_PI * ( shininess * 0.5 + 1.0 ) * pow( dotNH, shininess );
}
vec3 BRDF_BlinnPhong( const in vec3 lightDir, const in vec3 viewDir, const in vec3 normal, const in vec3 specularColor, const in float shininess ) {
	vec3 halfDir = normalize( lightDir + viewDir );
	float dotNH = saturate( dot( normal, halfDir ) );
	float dotVH = saturate( dot( viewDir, halfDir ) );
	vec3 F = F_Schlick( specularColor, 1.0, dotVH );
	float G = G_BlinnPhong_Implicit( );
	float D = D_BlinnPhong( shininess, dotNH );
	return F * ( G * D );
} // validated`,$b=`#ifdef USE_IRIDESCENCE
	const mat3 XYZ_TO_REC709 = mat3(
		 3.2404542, -0.9692660,  0.0556434,
		-1.5371385,  1.8760108, -0.2040259,
		-0.4985314,  0.0415560,  1.0572252
	);
	vec3 Fresnel0ToIor( vec3 fresnel0 ) {
		vec3 sqrtF0 = sqrt( fresnel0 );
		return ( vec3( 1.0 ) + sqrtF0 ) / ( vec3( 1.0 ) - sqrtF0 );
	}
	vec3 IorToFresnel0( vec3 transmittedIor, float incidentIor ) {
		return pow2( ( transmittedIor - vec3( incidentIor ) ) / ( transmittedIor + vec3( incidentIor ) ) );
	}
	float IorToFresnel0( float transmittedIor, float incidentIor ) {
		return pow2( ( transmittedIor - incidentIor ) / ( transmittedIor + incidentIor ));
	}
	vec3 evalSensitivity( float OPD, vec3 shift ) {
		float phase = 2.0 * PI * OPD * 1.0e-9;
		vec3 val = vec3( 5.4856e-13, 4.4201e-13, 5.2481e-13 );
		vec3 pos = vec3( 1.6810e+06, 1.7953e+06, 2.2084e+06 );
		vec3 var = vec3( 4.3278e+09, 9.3046e+09, 6.6121e+09 );
		vec3 xyz = val * sqrt( 2.0 * PI * var ) * cos( pos * phase + shift ) * exp( - pow2( phase ) * var );
		xyz.x += 9.7470e-14 * sqrt( 2.0 * PI * 4.5282e+09 ) * cos( 2.2399e+06 * phase + shift[ 0 ] ) * exp( - 4.5282e+09 * pow2( phase ) );
		xyz /= 1.0685e-7;
		vec3 rgb = XYZ_TO_REC709 * xyz;
		return rgb;
	}
	vec3 evalIridescence( float outsideIOR, float eta2, float cosTheta1, float thinFilmThickness, vec3 baseF0 ) {
		vec3 I;
		float iridescenceIOR = mix( outsideIOR, eta2, smoothstep( 0.0, 0.03, thinFilmThickness ) );
		float sinTheta2Sq = pow2( outsideIOR / iridescenceIOR ) * ( 1.0 - pow2( cosTheta1 ) );
		float cosTheta2Sq = 1.0 - sinTheta2Sq;
		if ( cosTheta2Sq < 0.0 ) {
			return vec3( 1.0 );
		}
		float cosTheta2 = sqrt( cosTheta2Sq );
		float R0 = IorToFresnel0( iridescenceIOR, outsideIOR );
		float R12 = F_Schlick( R0, 1.0, cosTheta1 );
		float T121 = 1.0 - R12;
		float phi12 = 0.0;
		if ( iridescenceIOR < outsideIOR ) phi12 = PI;
		float phi21 = PI - phi12;
		vec3 baseIOR = Fresnel0ToIor( clamp( baseF0, 0.0, 0.9999 ) );		vec3 R1 = IorToFresnel0( baseIOR, iridescenceIOR );
		vec3 R23 = F_Schlick( R1, 1.0, cosTheta2 );
		vec3 phi23 = vec3( 0.0 );
		if ( baseIOR[ 0 ] < iridescenceIOR ) phi23[ 0 ] = PI;
		if ( baseIOR[ 1 ] < iridescenceIOR ) phi23[ 1 ] = PI;
		if ( baseIOR[ 2 ] < iridescenceIOR ) phi23[ 2 ] = PI;
		float OPD = 2.0 * iridescenceIOR * thinFilmThickness * cosTheta2;
		vec3 phi = vec3( phi21 ) + phi23;
		vec3 R123 = clamp( R12 * R23, 1e-5, 0.9999 );
		vec3 r123 = sqrt( R123 );
		vec3 Rs = pow2( T121 ) * R23 / ( vec3( 1.0 ) - R123 );
		vec3 C0 = R12 + Rs;
		I = C0;
		vec3 Cm = Rs - T121;
		for ( int m = 1; m <= 2; ++ m ) {
			Cm *= r123;
			vec3 Sm = 2.0 * evalSensitivity( float( m ) * OPD, float( m ) * phi );
			I += Cm * Sm;
		}
		return max( I, vec3( 0.0 ) );
	}
#endif`,em=`#ifdef USE_BUMPMAP
	uniform sampler2D bumpMap;
	uniform float bumpScale;
	vec2 dHdxy_fwd() {
		vec2 dSTdx = dFdx( vBumpMapUv );
		vec2 dSTdy = dFdy( vBumpMapUv );
		float Hll = bumpScale * texture2D( bumpMap, vBumpMapUv ).x;
		float dBx = bumpScale * texture2D( bumpMap, vBumpMapUv + dSTdx ).x - Hll;
		float dBy = bumpScale * texture2D( bumpMap, vBumpMapUv + dSTdy ).x - Hll;
		return vec2( dBx, dBy );
	}
	vec3 perturbNormalArb( vec3 surf_pos, vec3 surf_norm, vec2 dHdxy, float faceDirection ) {
		vec3 vSigmaX = normalize( dFdx( surf_pos.xyz ) );
		vec3 vSigmaY = normalize( dFdy( surf_pos.xyz ) );
		vec3 vN = surf_norm;
		vec3 R1 = cross( vSigmaY, vN );
		vec3 R2 = cross( vN, vSigmaX );
		float fDet = dot( vSigmaX, R1 ) * faceDirection;
		vec3 vGrad = sign( fDet ) * ( dHdxy.x * R1 + dHdxy.y * R2 );
		return normalize( abs( fDet ) * surf_norm - vGrad );
	}
#endif`,tm=`#if NUM_CLIPPING_PLANES > 0
	vec4 plane;
	#ifdef ALPHA_TO_COVERAGE
		float distanceToPlane, distanceGradient;
		float clipOpacity = 1.0;
		#pragma unroll_loop_start
		for ( int i = 0; i < UNION_CLIPPING_PLANES; i ++ ) {
			plane = clippingPlanes[ i ];
			distanceToPlane = - dot( vClipPosition, plane.xyz ) + plane.w;
			distanceGradient = fwidth( distanceToPlane ) / 2.0;
			clipOpacity *= smoothstep( - distanceGradient, distanceGradient, distanceToPlane );
			if ( clipOpacity == 0.0 ) discard;
		}
		#pragma unroll_loop_end
		#if UNION_CLIPPING_PLANES < NUM_CLIPPING_PLANES
			float unionClipOpacity = 1.0;
			#pragma unroll_loop_start
			for ( int i = UNION_CLIPPING_PLANES; i < NUM_CLIPPING_PLANES; i ++ ) {
				plane = clippingPlanes[ i ];
				distanceToPlane = - dot( vClipPosition, plane.xyz ) + plane.w;
				distanceGradient = fwidth( distanceToPlane ) / 2.0;
				unionClipOpacity *= 1.0 - smoothstep( - distanceGradient, distanceGradient, distanceToPlane );
			}
			#pragma unroll_loop_end
			clipOpacity *= 1.0 - unionClipOpacity;
		#endif
		diffuseColor.a *= clipOpacity;
		if ( diffuseColor.a == 0.0 ) discard;
	#else
		#pragma unroll_loop_start
		for ( int i = 0; i < UNION_CLIPPING_PLANES; i ++ ) {
			plane = clippingPlanes[ i ];
			if ( dot( vClipPosition, plane.xyz ) > plane.w ) discard;
		}
		#pragma unroll_loop_end
		#if UNION_CLIPPING_PLANES < NUM_CLIPPING_PLANES
			bool clipped = true;
			#pragma unroll_loop_start
			for ( int i = UNION_CLIPPING_PLANES; i < NUM_CLIPPING_PLANES; i ++ ) {
				plane = clippingPlanes[ i ];
				clipped = ( dot( vClipPosition, plane.xyz ) > plane.w ) && clipped;
			}
			#pragma unroll_loop_end
			if ( clipped ) discard;
		#endif
	#endif
#endif`,am=`#if NUM_CLIPPING_PLANES > 0
	varying vec3 vClipPosition;
	uniform vec4 clippingPlanes[ NUM_CLIPPING_PLANES ];
#endif`,nm=`#if NUM_CLIPPING_PLANES > 0
	varying vec3 vClipPosition;
#endif`,im=`#if NUM_CLIPPING_PLANES > 0
	vClipPosition = - mvPosition.xyz;
#endif`,rm=`#if defined( USE_COLOR_ALPHA )
	diffuseColor *= vColor;
#elif defined( USE_COLOR )
	diffuseColor.rgb *= vColor;
#endif`,sm=`#if defined( USE_COLOR_ALPHA )
	varying vec4 vColor;
#elif defined( USE_COLOR )
	varying vec3 vColor;
#endif`,om=`#if defined( USE_COLOR_ALPHA )
	varying vec4 vColor;
#elif defined( USE_COLOR ) || defined( USE_INSTANCING_COLOR ) || defined( USE_BATCHING_COLOR )
	varying vec3 vColor;
#endif`,cm=`#if defined( USE_COLOR_ALPHA )
	vColor = vec4( 1.0 );
#elif defined( USE_COLOR ) || defined( USE_INSTANCING_COLOR ) || defined( USE_BATCHING_COLOR )
	vColor = vec3( 1.0 );
#endif
#ifdef USE_COLOR
	vColor *= color;
#endif
#ifdef USE_INSTANCING_COLOR
	vColor.xyz *= instanceColor.xyz;
#endif
#ifdef USE_BATCHING_COLOR
	vec3 batchingColor = getBatchingColor( getIndirectIndex( gl_DrawID ) );
	vColor.xyz *= batchingColor.xyz;
#endif`,hm=`#define PI 3.141592653589793
#define PI2 6.283185307179586
#define PI_HALF 1.5707963267948966
#define RECIPROCAL_PI 0.3183098861837907
#define RECIPROCAL_PI2 0.15915494309189535
#define EPSILON 1e-6
#ifndef saturate
#define saturate( a ) clamp( a, 0.0, 1.0 )
#endif
#define whiteComplement( a ) ( 1.0 - saturate( a ) )
float pow2( const in float x ) { return x*x; }
vec3 pow2( const in vec3 x ) { return x*x; }
float pow3( const in float x ) { return x*x*x; }
float pow4( const in float x ) { float x2 = x*x; return x2*x2; }
float max3( const in vec3 v ) { return max( max( v.x, v.y ), v.z ); }
float average( const in vec3 v ) { return dot( v, vec3( 0.3333333 ) ); }
highp float rand( const in vec2 uv ) {
	const highp float a = 12.9898, b = 78.233, c = 43758.5453;
	highp float dt = dot( uv.xy, vec2( a,b ) ), sn = mod( dt, PI );
	return fract( sin( sn ) * c );
}
#ifdef HIGH_PRECISION
	float precisionSafeLength( vec3 v ) { return length( v ); }
#else
	float precisionSafeLength( vec3 v ) {
		float maxComponent = max3( abs( v ) );
		return length( v / maxComponent ) * maxComponent;
	}
#endif
struct IncidentLight {
	vec3 color;
	vec3 direction;
	bool visible;
};
struct ReflectedLight {
	vec3 directDiffuse;
	vec3 directSpecular;
	vec3 indirectDiffuse;
	vec3 indirectSpecular;
};
#ifdef USE_ALPHAHASH
	varying vec3 vPosition;
#endif
vec3 transformDirection( in vec3 dir, in mat4 matrix ) {
	return normalize( ( matrix * vec4( dir, 0.0 ) ).xyz );
}
vec3 inverseTransformDirection( in vec3 dir, in mat4 matrix ) {
	return normalize( ( vec4( dir, 0.0 ) * matrix ).xyz );
}
mat3 transposeMat3( const in mat3 m ) {
	mat3 tmp;
	tmp[ 0 ] = vec3( m[ 0 ].x, m[ 1 ].x, m[ 2 ].x );
	tmp[ 1 ] = vec3( m[ 0 ].y, m[ 1 ].y, m[ 2 ].y );
	tmp[ 2 ] = vec3( m[ 0 ].z, m[ 1 ].z, m[ 2 ].z );
	return tmp;
}
bool isPerspectiveMatrix( mat4 m ) {
	return m[ 2 ][ 3 ] == - 1.0;
}
vec2 equirectUv( in vec3 dir ) {
	float u = atan( dir.z, dir.x ) * RECIPROCAL_PI2 + 0.5;
	float v = asin( clamp( dir.y, - 1.0, 1.0 ) ) * RECIPROCAL_PI + 0.5;
	return vec2( u, v );
}
vec3 BRDF_Lambert( const in vec3 diffuseColor ) {
	return RECIPROCAL_PI * diffuseColor;
}
vec3 F_Schlick( const in vec3 f0, const in float f90, const in float dotVH ) {
	float fresnel = exp2( ( - 5.55473 * dotVH - 6.98316 ) * dotVH );
	return f0 * ( 1.0 - fresnel ) + ( f90 * fresnel );
}
float F_Schlick( const in float f0, const in float f90, const in float dotVH ) {
	float fresnel = exp2( ( - 5.55473 * dotVH - 6.98316 ) * dotVH );
	return f0 * ( 1.0 - fresnel ) + ( f90 * fresnel );
} // validated`,lm=`#ifdef ENVMAP_TYPE_CUBE_UV
	#define cubeUV_minMipLevel 4.0
	#define cubeUV_minTileSize 16.0
	float getFace( vec3 direction ) {
		vec3 absDirection = abs( direction );
		float face = - 1.0;
		if ( absDirection.x > absDirection.z ) {
			if ( absDirection.x > absDirection.y )
				face = direction.x > 0.0 ? 0.0 : 3.0;
			else
				face = direction.y > 0.0 ? 1.0 : 4.0;
		} else {
			if ( absDirection.z > absDirection.y )
				face = direction.z > 0.0 ? 2.0 : 5.0;
			else
				face = direction.y > 0.0 ? 1.0 : 4.0;
		}
		return face;
	}
	vec2 getUV( vec3 direction, float face ) {
		vec2 uv;
		if ( face == 0.0 ) {
			uv = vec2( direction.z, direction.y ) / abs( direction.x );
		} else if ( face == 1.0 ) {
			uv = vec2( - direction.x, - direction.z ) / abs( direction.y );
		} else if ( face == 2.0 ) {
			uv = vec2( - direction.x, direction.y ) / abs( direction.z );
		} else if ( face == 3.0 ) {
			uv = vec2( - direction.z, direction.y ) / abs( direction.x );
		} else if ( face == 4.0 ) {
			uv = vec2( - direction.x, direction.z ) / abs( direction.y );
		} else {
			uv = vec2( direction.x, direction.y ) / abs( direction.z );
		}
		return 0.5 * ( uv + 1.0 );
	}
	vec3 bilinearCubeUV( sampler2D envMap, vec3 direction, float mipInt ) {
		float face = getFace( direction );
		float filterInt = max( cubeUV_minMipLevel - mipInt, 0.0 );
		mipInt = max( mipInt, cubeUV_minMipLevel );
		float faceSize = exp2( mipInt );
		highp vec2 uv = getUV( direction, face ) * ( faceSize - 2.0 ) + 1.0;
		if ( face > 2.0 ) {
			uv.y += faceSize;
			face -= 3.0;
		}
		uv.x += face * faceSize;
		uv.x += filterInt * 3.0 * cubeUV_minTileSize;
		uv.y += 4.0 * ( exp2( CUBEUV_MAX_MIP ) - faceSize );
		uv.x *= CUBEUV_TEXEL_WIDTH;
		uv.y *= CUBEUV_TEXEL_HEIGHT;
		#ifdef texture2DGradEXT
			return texture2DGradEXT( envMap, uv, vec2( 0.0 ), vec2( 0.0 ) ).rgb;
		#else
			return texture2D( envMap, uv ).rgb;
		#endif
	}
	#define cubeUV_r0 1.0
	#define cubeUV_m0 - 2.0
	#define cubeUV_r1 0.8
	#define cubeUV_m1 - 1.0
	#define cubeUV_r4 0.4
	#define cubeUV_m4 2.0
	#define cubeUV_r5 0.305
	#define cubeUV_m5 3.0
	#define cubeUV_r6 0.21
	#define cubeUV_m6 4.0
	float roughnessToMip( float roughness ) {
		float mip = 0.0;
		if ( roughness >= cubeUV_r1 ) {
			mip = ( cubeUV_r0 - roughness ) * ( cubeUV_m1 - cubeUV_m0 ) / ( cubeUV_r0 - cubeUV_r1 ) + cubeUV_m0;
		} else if ( roughness >= cubeUV_r4 ) {
			mip = ( cubeUV_r1 - roughness ) * ( cubeUV_m4 - cubeUV_m1 ) / ( cubeUV_r1 - cubeUV_r4 ) + cubeUV_m1;
		} else if ( roughness >= cubeUV_r5 ) {
			mip = ( cubeUV_r4 - roughness ) * ( cubeUV_m5 - cubeUV_m4 ) / ( cubeUV_r4 - cubeUV_r5 ) + cubeUV_m4;
		} else if ( roughness >= cubeUV_r6 ) {
			mip = ( cubeUV_r5 - roughness ) * ( cubeUV_m6 - cubeUV_m5 ) / ( cubeUV_r5 - cubeUV_r6 ) + cubeUV_m5;
		} else {
			mip = - 2.0 * log2( 1.16 * roughness );		}
		return mip;
	}
	vec4 textureCubeUV( sampler2D envMap, vec3 sampleDir, float roughness ) {
		float mip = clamp( roughnessToMip( roughness ), cubeUV_m0, CUBEUV_MAX_MIP );
		float mipF = fract( mip );
		float mipInt = floor( mip );
		vec3 color0 = bilinearCubeUV( envMap, sampleDir, mipInt );
		if ( mipF == 0.0 ) {
			return vec4( color0, 1.0 );
		} else {
			vec3 color1 = bilinearCubeUV( envMap, sampleDir, mipInt + 1.0 );
			return vec4( mix( color0, color1, mipF ), 1.0 );
		}
	}
#endif`,dm=`vec3 transformedNormal = objectNormal;
#ifdef USE_TANGENT
	vec3 transformedTangent = objectTangent;
#endif
#ifdef USE_BATCHING
	mat3 bm = mat3( batchingMatrix );
	transformedNormal /= vec3( dot( bm[ 0 ], bm[ 0 ] ), dot( bm[ 1 ], bm[ 1 ] ), dot( bm[ 2 ], bm[ 2 ] ) );
	transformedNormal = bm * transformedNormal;
	#ifdef USE_TANGENT
		transformedTangent = bm * transformedTangent;
	#endif
#endif
#ifdef USE_INSTANCING
	mat3 im = mat3( instanceMatrix );
	transformedNormal /= vec3( dot( im[ 0 ], im[ 0 ] ), dot( im[ 1 ], im[ 1 ] ), dot( im[ 2 ], im[ 2 ] ) );
	transformedNormal = im * transformedNormal;
	#ifdef USE_TANGENT
		transformedTangent = im * transformedTangent;
	#endif
#endif
transformedNormal = normalMatrix * transformedNormal;
#ifdef FLIP_SIDED
	transformedNormal = - transformedNormal;
#endif
#ifdef USE_TANGENT
	transformedTangent = ( modelViewMatrix * vec4( transformedTangent, 0.0 ) ).xyz;
	#ifdef FLIP_SIDED
		transformedTangent = - transformedTangent;
	#endif
#endif`,fm=`#ifdef USE_DISPLACEMENTMAP
	uniform sampler2D displacementMap;
	uniform float displacementScale;
	uniform float displacementBias;
#endif`,um=`#ifdef USE_DISPLACEMENTMAP
	transformed += normalize( objectNormal ) * ( texture2D( displacementMap, vDisplacementMapUv ).x * displacementScale + displacementBias );
#endif`,bm=`#ifdef USE_EMISSIVEMAP
	vec4 emissiveColor = texture2D( emissiveMap, vEmissiveMapUv );
	#ifdef DECODE_VIDEO_TEXTURE_EMISSIVE
		emissiveColor = sRGBTransferEOTF( emissiveColor );
	#endif
	totalEmissiveRadiance *= emissiveColor.rgb;
#endif`,mm=`#ifdef USE_EMISSIVEMAP
	uniform sampler2D emissiveMap;
#endif`,pm="gl_FragColor = linearToOutputTexel( gl_FragColor );",gm=`vec4 LinearTransferOETF( in vec4 value ) {
	return value;
}
vec4 sRGBTransferEOTF( in vec4 value ) {
	return vec4( mix( pow( value.rgb * 0.9478672986 + vec3( 0.0521327014 ), vec3( 2.4 ) ), value.rgb * 0.0773993808, vec3( lessThanEqual( value.rgb, vec3( 0.04045 ) ) ) ), value.a );
}
vec4 sRGBTransferOETF( in vec4 value ) {
	return vec4( mix( pow( value.rgb, vec3( 0.41666 ) ) * 1.055 - vec3( 0.055 ), value.rgb * 12.92, vec3( lessThanEqual( value.rgb, vec3( 0.0031308 ) ) ) ), value.a );
}`,vm=`#ifdef USE_ENVMAP
	#ifdef ENV_WORLDPOS
		vec3 cameraToFrag;
		if ( isOrthographic ) {
			cameraToFrag = normalize( vec3( - viewMatrix[ 0 ][ 2 ], - viewMatrix[ 1 ][ 2 ], - viewMatrix[ 2 ][ 2 ] ) );
		} else {
			cameraToFrag = normalize( vWorldPosition - cameraPosition );
		}
		vec3 worldNormal = inverseTransformDirection( normal, viewMatrix );
		#ifdef ENVMAP_MODE_REFLECTION
			vec3 reflectVec = reflect( cameraToFrag, worldNormal );
		#else
			vec3 reflectVec = refract( cameraToFrag, worldNormal, refractionRatio );
		#endif
	#else
		vec3 reflectVec = vReflect;
	#endif
	#ifdef ENVMAP_TYPE_CUBE
		vec4 envColor = textureCube( envMap, envMapRotation * vec3( flipEnvMap * reflectVec.x, reflectVec.yz ) );
	#else
		vec4 envColor = vec4( 0.0 );
	#endif
	#ifdef ENVMAP_BLENDING_MULTIPLY
		outgoingLight = mix( outgoingLight, outgoingLight * envColor.xyz, specularStrength * reflectivity );
	#elif defined( ENVMAP_BLENDING_MIX )
		outgoingLight = mix( outgoingLight, envColor.xyz, specularStrength * reflectivity );
	#elif defined( ENVMAP_BLENDING_ADD )
		outgoingLight += envColor.xyz * specularStrength * reflectivity;
	#endif
#endif`,ym=`#ifdef USE_ENVMAP
	uniform float envMapIntensity;
	uniform float flipEnvMap;
	uniform mat3 envMapRotation;
	#ifdef ENVMAP_TYPE_CUBE
		uniform samplerCube envMap;
	#else
		uniform sampler2D envMap;
	#endif
	
#endif`,xm=`#ifdef USE_ENVMAP
	uniform float reflectivity;
	#if defined( USE_BUMPMAP ) || defined( USE_NORMALMAP ) || defined( PHONG ) || defined( LAMBERT )
		#define ENV_WORLDPOS
	#endif
	#ifdef ENV_WORLDPOS
		varying vec3 vWorldPosition;
		uniform float refractionRatio;
	#else
		varying vec3 vReflect;
	#endif
#endif`,wm=`#ifdef USE_ENVMAP
	#if defined( USE_BUMPMAP ) || defined( USE_NORMALMAP ) || defined( PHONG ) || defined( LAMBERT )
		#define ENV_WORLDPOS
	#endif
	#ifdef ENV_WORLDPOS
		
		varying vec3 vWorldPosition;
	#else
		varying vec3 vReflect;
		uniform float refractionRatio;
	#endif
#endif`,Mm=`#ifdef USE_ENVMAP
	#ifdef ENV_WORLDPOS
		vWorldPosition = worldPosition.xyz;
	#else
		vec3 cameraToVertex;
		if ( isOrthographic ) {
			cameraToVertex = normalize( vec3( - viewMatrix[ 0 ][ 2 ], - viewMatrix[ 1 ][ 2 ], - viewMatrix[ 2 ][ 2 ] ) );
		} else {
			cameraToVertex = normalize( worldPosition.xyz - cameraPosition );
		}
		vec3 worldNormal = inverseTransformDirection( transformedNormal, viewMatrix );
		#ifdef ENVMAP_MODE_REFLECTION
			vReflect = reflect( cameraToVertex, worldNormal );
		#else
			vReflect = refract( cameraToVertex, worldNormal, refractionRatio );
		#endif
	#endif
#endif`,_m=`#ifdef USE_FOG
	vFogDepth = - mvPosition.z;
#endif`,Em=`#ifdef USE_FOG
	varying float vFogDepth;
#endif`,Sm=`#ifdef USE_FOG
	#ifdef FOG_EXP2
		float fogFactor = 1.0 - exp( - fogDensity * fogDensity * vFogDepth * vFogDepth );
	#else
		float fogFactor = smoothstep( fogNear, fogFar, vFogDepth );
	#endif
	gl_FragColor.rgb = mix( gl_FragColor.rgb, fogColor, fogFactor );
#endif`,Am=`#ifdef USE_FOG
	uniform vec3 fogColor;
	varying float vFogDepth;
	#ifdef FOG_EXP2
		uniform float fogDensity;
	#else
		uniform float fogNear;
		uniform float fogFar;
	#endif
#endif`,Tm=`#ifdef USE_GRADIENTMAP
	uniform sampler2D gradientMap;
#endif
vec3 getGradientIrradiance( vec3 normal, vec3 lightDirection ) {
	float dotNL = dot( normal, lightDirection );
	vec2 coord = vec2( dotNL * 0.5 + 0.5, 0.0 );
	#ifdef USE_GRADIENTMAP
		return vec3( texture2D( gradientMap, coord ).r );
	#else
		vec2 fw = fwidth( coord ) * 0.5;
		return mix( vec3( 0.7 ), vec3( 1.0 ), smoothstep( 0.7 - fw.x, 0.7 + fw.x, coord.x ) );
	#endif
}`,km=`#ifdef USE_LIGHTMAP
	uniform sampler2D lightMap;
	uniform float lightMapIntensity;
#endif`,Rm=`LambertMaterial material;
material.diffuseColor = diffuseColor.rgb;
material.specularStrength = specularStrength;`,Cm=`varying vec3 vViewPosition;
struct LambertMaterial {
	vec3 diffuseColor;
	float specularStrength;
};
void RE_Direct_Lambert( const in IncidentLight directLight, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in LambertMaterial material, inout ReflectedLight reflectedLight ) {
	float dotNL = saturate( dot( geometryNormal, directLight.direction ) );
	vec3 irradiance = dotNL * directLight.color;
	reflectedLight.directDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
}
void RE_IndirectDiffuse_Lambert( const in vec3 irradiance, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in LambertMaterial material, inout ReflectedLight reflectedLight ) {
	reflectedLight.indirectDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
}
#define RE_Direct				RE_Direct_Lambert
#define RE_IndirectDiffuse		RE_IndirectDiffuse_Lambert`,Im=`uniform bool receiveShadow;
uniform vec3 ambientLightColor;
#if defined( USE_LIGHT_PROBES )
	uniform vec3 lightProbe[ 9 ];
#endif
vec3 shGetIrradianceAt( in vec3 normal, in vec3 shCoefficients[ 9 ] ) {
	float x = normal.x, y = normal.y, z = normal.z;
	vec3 result = shCoefficients[ 0 ] * 0.886227;
	result += shCoefficients[ 1 ] * 2.0 * 0.511664 * y;
	result += shCoefficients[ 2 ] * 2.0 * 0.511664 * z;
	result += shCoefficients[ 3 ] * 2.0 * 0.511664 * x;
	result += shCoefficients[ 4 ] * 2.0 * 0.429043 * x * y;
	result += shCoefficients[ 5 ] * 2.0 * 0.429043 * y * z;
	result += shCoefficients[ 6 ] * ( 0.743125 * z * z - 0.247708 );
	result += shCoefficients[ 7 ] * 2.0 * 0.429043 * x * z;
	result += shCoefficients[ 8 ] * 0.429043 * ( x * x - y * y );
	return result;
}
vec3 getLightProbeIrradiance( const in vec3 lightProbe[ 9 ], const in vec3 normal ) {
	vec3 worldNormal = inverseTransformDirection( normal, viewMatrix );
	vec3 irradiance = shGetIrradianceAt( worldNormal, lightProbe );
	return irradiance;
}
vec3 getAmbientLightIrradiance( const in vec3 ambientLightColor ) {
	vec3 irradiance = ambientLightColor;
	return irradiance;
}
float getDistanceAttenuation( const in float lightDistance, const in float cutoffDistance, const in float decayExponent ) {
	float distanceFalloff = 1.0 / max( pow( lightDistance, decayExponent ), 0.01 );
	if ( cutoffDistance > 0.0 ) {
		distanceFalloff *= pow2( saturate( 1.0 - pow4( lightDistance / cutoffDistance ) ) );
	}
	return distanceFalloff;
}
float getSpotAttenuation( const in float coneCosine, const in float penumbraCosine, const in float angleCosine ) {
	return smoothstep( coneCosine, penumbraCosine, angleCosine );
}
#if NUM_DIR_LIGHTS > 0
	struct DirectionalLight {
		vec3 direction;
		vec3 color;
	};
	uniform DirectionalLight directionalLights[ NUM_DIR_LIGHTS ];
	void getDirectionalLightInfo( const in DirectionalLight directionalLight, out IncidentLight light ) {
		light.color = directionalLight.color;
		light.direction = directionalLight.direction;
		light.visible = true;
	}
#endif
#if NUM_POINT_LIGHTS > 0
	struct PointLight {
		vec3 position;
		vec3 color;
		float distance;
		float decay;
	};
	uniform PointLight pointLights[ NUM_POINT_LIGHTS ];
	void getPointLightInfo( const in PointLight pointLight, const in vec3 geometryPosition, out IncidentLight light ) {
		vec3 lVector = pointLight.position - geometryPosition;
		light.direction = normalize( lVector );
		float lightDistance = length( lVector );
		light.color = pointLight.color;
		light.color *= getDistanceAttenuation( lightDistance, pointLight.distance, pointLight.decay );
		light.visible = ( light.color != vec3( 0.0 ) );
	}
#endif
#if NUM_SPOT_LIGHTS > 0
	struct SpotLight {
		vec3 position;
		vec3 direction;
		vec3 color;
		float distance;
		float decay;
		float coneCos;
		float penumbraCos;
	};
	uniform SpotLight spotLights[ NUM_SPOT_LIGHTS ];
	void getSpotLightInfo( const in SpotLight spotLight, const in vec3 geometryPosition, out IncidentLight light ) {
		vec3 lVector = spotLight.position - geometryPosition;
		light.direction = normalize( lVector );
		float angleCos = dot( light.direction, spotLight.direction );
		float spotAttenuation = getSpotAttenuation( spotLight.coneCos, spotLight.penumbraCos, angleCos );
		if ( spotAttenuation > 0.0 ) {
			float lightDistance = length( lVector );
			light.color = spotLight.color * spotAttenuation;
			light.color *= getDistanceAttenuation( lightDistance, spotLight.distance, spotLight.decay );
			light.visible = ( light.color != vec3( 0.0 ) );
		} else {
			light.color = vec3( 0.0 );
			light.visible = false;
		}
	}
#endif
#if NUM_RECT_AREA_LIGHTS > 0
	struct RectAreaLight {
		vec3 color;
		vec3 position;
		vec3 halfWidth;
		vec3 halfHeight;
	};
	uniform sampler2D ltc_1;	uniform sampler2D ltc_2;
	uniform RectAreaLight rectAreaLights[ NUM_RECT_AREA_LIGHTS ];
#endif
#if NUM_HEMI_LIGHTS > 0
	struct HemisphereLight {
		vec3 direction;
		vec3 skyColor;
		vec3 groundColor;
	};
	uniform HemisphereLight hemisphereLights[ NUM_HEMI_LIGHTS ];
	vec3 getHemisphereLightIrradiance( const in HemisphereLight hemiLight, const in vec3 normal ) {
		float dotNL = dot( normal, hemiLight.direction );
		float hemiDiffuseWeight = 0.5 * dotNL + 0.5;
		vec3 irradiance = mix( hemiLight.groundColor, hemiLight.skyColor, hemiDiffuseWeight );
		return irradiance;
	}
#endif`,Pm=`#ifdef USE_ENVMAP
	vec3 getIBLIrradiance( const in vec3 normal ) {
		#ifdef ENVMAP_TYPE_CUBE_UV
			vec3 worldNormal = inverseTransformDirection( normal, viewMatrix );
			vec4 envMapColor = textureCubeUV( envMap, envMapRotation * worldNormal, 1.0 );
			return PI * envMapColor.rgb * envMapIntensity;
		#else
			return vec3( 0.0 );
		#endif
	}
	vec3 getIBLRadiance( const in vec3 viewDir, const in vec3 normal, const in float roughness ) {
		#ifdef ENVMAP_TYPE_CUBE_UV
			vec3 reflectVec = reflect( - viewDir, normal );
			reflectVec = normalize( mix( reflectVec, normal, roughness * roughness) );
			reflectVec = inverseTransformDirection( reflectVec, viewMatrix );
			vec4 envMapColor = textureCubeUV( envMap, envMapRotation * reflectVec, roughness );
			return envMapColor.rgb * envMapIntensity;
		#else
			return vec3( 0.0 );
		#endif
	}
	#ifdef USE_ANISOTROPY
		vec3 getIBLAnisotropyRadiance( const in vec3 viewDir, const in vec3 normal, const in float roughness, const in vec3 bitangent, const in float anisotropy ) {
			#ifdef ENVMAP_TYPE_CUBE_UV
				vec3 bentNormal = cross( bitangent, viewDir );
				bentNormal = normalize( cross( bentNormal, bitangent ) );
				bentNormal = normalize( mix( bentNormal, normal, pow2( pow2( 1.0 - anisotropy * ( 1.0 - roughness ) ) ) ) );
				return getIBLRadiance( viewDir, bentNormal, roughness );
			#else
				return vec3( 0.0 );
			#endif
		}
	#endif
#endif`,Dm=`ToonMaterial material;
material.diffuseColor = diffuseColor.rgb;`,Nm=`varying vec3 vViewPosition;
struct ToonMaterial {
	vec3 diffuseColor;
};
void RE_Direct_Toon( const in IncidentLight directLight, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in ToonMaterial material, inout ReflectedLight reflectedLight ) {
	vec3 irradiance = getGradientIrradiance( geometryNormal, directLight.direction ) * directLight.color;
	reflectedLight.directDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
}
void RE_IndirectDiffuse_Toon( const in vec3 irradiance, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in ToonMaterial material, inout ReflectedLight reflectedLight ) {
	reflectedLight.indirectDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
}
#define RE_Direct				RE_Direct_Toon
#define RE_IndirectDiffuse		RE_IndirectDiffuse_Toon`,Um=`BlinnPhongMaterial material;
material.diffuseColor = diffuseColor.rgb;
material.specularColor = specular;
material.specularShininess = shininess;
material.specularStrength = specularStrength;`,Fm=`varying vec3 vViewPosition;
struct BlinnPhongMaterial {
	vec3 diffuseColor;
	vec3 specularColor;
	float specularShininess;
	float specularStrength;
};
void RE_Direct_BlinnPhong( const in IncidentLight directLight, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in BlinnPhongMaterial material, inout ReflectedLight reflectedLight ) {
	float dotNL = saturate( dot( geometryNormal, directLight.direction ) );
	vec3 irradiance = dotNL * directLight.color;
	reflectedLight.directDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
	reflectedLight.directSpecular += irradiance * BRDF_BlinnPhong( directLight.direction, geometryViewDir, geometryNormal, material.specularColor, material.specularShininess ) * material.specularStrength;
}
void RE_IndirectDiffuse_BlinnPhong( const in vec3 irradiance, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in BlinnPhongMaterial material, inout ReflectedLight reflectedLight ) {
	reflectedLight.indirectDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
}
#define RE_Direct				RE_Direct_BlinnPhong
#define RE_IndirectDiffuse		RE_IndirectDiffuse_BlinnPhong`,Lm=`PhysicalMaterial material;
material.diffuseColor = diffuseColor.rgb * ( 1.0 - metalnessFactor );
vec3 dxy = max( abs( dFdx( nonPerturbedNormal ) ), abs( dFdy( nonPerturbedNormal ) ) );
float geometryRoughness = max( max( dxy.x, dxy.y ), dxy.z );
material.roughness = max( roughnessFactor, 0.0525 );material.roughness += geometryRoughness;
material.roughness = min( material.roughness, 1.0 );
#ifdef IOR
	material.ior = ior;
	#ifdef USE_SPECULAR
		float specularIntensityFactor = specularIntensity;
		vec3 specularColorFactor = specularColor;
		#ifdef USE_SPECULAR_COLORMAP
			specularColorFactor *= texture2D( specularColorMap, vSpecularColorMapUv ).rgb;
		#endif
		#ifdef USE_SPECULAR_INTENSITYMAP
			specularIntensityFactor *= texture2D( specularIntensityMap, vSpecularIntensityMapUv ).a;
		#endif
		material.specularF90 = mix( specularIntensityFactor, 1.0, metalnessFactor );
	#else
		float specularIntensityFactor = 1.0;
		vec3 specularColorFactor = vec3( 1.0 );
		material.specularF90 = 1.0;
	#endif
	material.specularColor = mix( min( pow2( ( material.ior - 1.0 ) / ( material.ior + 1.0 ) ) * specularColorFactor, vec3( 1.0 ) ) * specularIntensityFactor, diffuseColor.rgb, metalnessFactor );
#else
	material.specularColor = mix( vec3( 0.04 ), diffuseColor.rgb, metalnessFactor );
	material.specularF90 = 1.0;
#endif
#ifdef USE_CLEARCOAT
	material.clearcoat = clearcoat;
	material.clearcoatRoughness = clearcoatRoughness;
	material.clearcoatF0 = vec3( 0.04 );
	material.clearcoatF90 = 1.0;
	#ifdef USE_CLEARCOATMAP
		material.clearcoat *= texture2D( clearcoatMap, vClearcoatMapUv ).x;
	#endif
	#ifdef USE_CLEARCOAT_ROUGHNESSMAP
		material.clearcoatRoughness *= texture2D( clearcoatRoughnessMap, vClearcoatRoughnessMapUv ).y;
	#endif
	material.clearcoat = saturate( material.clearcoat );	material.clearcoatRoughness = max( material.clearcoatRoughness, 0.0525 );
	material.clearcoatRoughness += geometryRoughness;
	material.clearcoatRoughness = min( material.clearcoatRoughness, 1.0 );
#endif
#ifdef USE_DISPERSION
	material.dispersion = dispersion;
#endif
#ifdef USE_IRIDESCENCE
	material.iridescence = iridescence;
	material.iridescenceIOR = iridescenceIOR;
	#ifdef USE_IRIDESCENCEMAP
		material.iridescence *= texture2D( iridescenceMap, vIridescenceMapUv ).r;
	#endif
	#ifdef USE_IRIDESCENCE_THICKNESSMAP
		material.iridescenceThickness = (iridescenceThicknessMaximum - iridescenceThicknessMinimum) * texture2D( iridescenceThicknessMap, vIridescenceThicknessMapUv ).g + iridescenceThicknessMinimum;
	#else
		material.iridescenceThickness = iridescenceThicknessMaximum;
	#endif
#endif
#ifdef USE_SHEEN
	material.sheenColor = sheenColor;
	#ifdef USE_SHEEN_COLORMAP
		material.sheenColor *= texture2D( sheenColorMap, vSheenColorMapUv ).rgb;
	#endif
	material.sheenRoughness = clamp( sheenRoughness, 0.07, 1.0 );
	#ifdef USE_SHEEN_ROUGHNESSMAP
		material.sheenRoughness *= texture2D( sheenRoughnessMap, vSheenRoughnessMapUv ).a;
	#endif
#endif
#ifdef USE_ANISOTROPY
	#ifdef USE_ANISOTROPYMAP
		mat2 anisotropyMat = mat2( anisotropyVector.x, anisotropyVector.y, - anisotropyVector.y, anisotropyVector.x );
		vec3 anisotropyPolar = texture2D( anisotropyMap, vAnisotropyMapUv ).rgb;
		vec2 anisotropyV = anisotropyMat * normalize( 2.0 * anisotropyPolar.rg - vec2( 1.0 ) ) * anisotropyPolar.b;
	#else
		vec2 anisotropyV = anisotropyVector;
	#endif
	material.anisotropy = length( anisotropyV );
	if( material.anisotropy == 0.0 ) {
		anisotropyV = vec2( 1.0, 0.0 );
	} else {
		anisotropyV /= material.anisotropy;
		material.anisotropy = saturate( material.anisotropy );
	}
	material.alphaT = mix( pow2( material.roughness ), 1.0, pow2( material.anisotropy ) );
	material.anisotropyT = tbn[ 0 ] * anisotropyV.x + tbn[ 1 ] * anisotropyV.y;
	material.anisotropyB = tbn[ 1 ] * anisotropyV.x - tbn[ 0 ] * anisotropyV.y;
#endif`,jm=`struct PhysicalMaterial {
	vec3 diffuseColor;
	float roughness;
	vec3 specularColor;
	float specularF90;
	float dispersion;
	#ifdef USE_CLEARCOAT
		float clearcoat;
		float clearcoatRoughness;
		vec3 clearcoatF0;
		float clearcoatF90;
	#endif
	#ifdef USE_IRIDESCENCE
		float iridescence;
		float iridescenceIOR;
		float iridescenceThickness;
		vec3 iridescenceFresnel;
		vec3 iridescenceF0;
	#endif
	#ifdef USE_SHEEN
		vec3 sheenColor;
		float sheenRoughness;
	#endif
	#ifdef IOR
		float ior;
	#endif
	#ifdef USE_TRANSMISSION
		float transmission;
		float transmissionAlpha;
		float thickness;
		float attenuationDistance;
		vec3 attenuationColor;
	#endif
	#ifdef USE_ANISOTROPY
		float anisotropy;
		float alphaT;
		vec3 anisotropyT;
		vec3 anisotropyB;
	#endif
};
vec3 clearcoatSpecularDirect = vec3( 0.0 );
vec3 clearcoatSpecularIndirect = vec3( 0.0 );
vec3 sheenSpecularDirect = vec3( 0.0 );
vec3 sheenSpecularIndirect = vec3(0.0 );
vec3 Schlick_to_F0( const in vec3 f, const in float f90, const in float dotVH ) {
    float x = clamp( 1.0 - dotVH, 0.0, 1.0 );
    float x2 = x * x;
    float x5 = clamp( x * x2 * x2, 0.0, 0.9999 );
    return ( f - vec3( f90 ) * x5 ) / ( 1.0 - x5 );
}
float V_GGX_SmithCorrelated( const in float alpha, const in float dotNL, const in float dotNV ) {
	float a2 = pow2( alpha );
	float gv = dotNL * sqrt( a2 + ( 1.0 - a2 ) * pow2( dotNV ) );
	float gl = dotNV * sqrt( a2 + ( 1.0 - a2 ) * pow2( dotNL ) );
	return 0.5 / max( gv + gl, EPSILON );
}
float D_GGX( const in float alpha, const in float dotNH ) {
	float a2 = pow2( alpha );
	float denom = pow2( dotNH ) * ( a2 - 1.0 ) + 1.0;
	return RECIPROCAL_PI * a2 / pow2( denom );
}
#ifdef USE_ANISOTROPY
	float V_GGX_SmithCorrelated_Anisotropic( const in float alphaT, const in float alphaB, const in float dotTV, const in float dotBV, const in float dotTL, const in float dotBL, const in float dotNV, const in float dotNL ) {
		float gv = dotNL * length( vec3( alphaT * dotTV, alphaB * dotBV, dotNV ) );
		float gl = dotNV * length( vec3( alphaT * dotTL, alphaB * dotBL, dotNL ) );
		float v = 0.5 / ( gv + gl );
		return saturate(v);
	}
	float D_GGX_Anisotropic( const in float alphaT, const in float alphaB, const in float dotNH, const in float dotTH, const in float dotBH ) {
		float a2 = alphaT * alphaB;
		highp vec3 v = vec3( alphaB * dotTH, alphaT * dotBH, a2 * dotNH );
		highp float v2 = dot( v, v );
		float w2 = a2 / v2;
		return RECIPROCAL_PI * a2 * pow2 ( w2 );
	}
#endif
#ifdef USE_CLEARCOAT
	vec3 BRDF_GGX_Clearcoat( const in vec3 lightDir, const in vec3 viewDir, const in vec3 normal, const in PhysicalMaterial material) {
		vec3 f0 = material.clearcoatF0;
		float f90 = material.clearcoatF90;
		float roughness = material.clearcoatRoughness;
		float alpha = pow2( roughness );
		vec3 halfDir = normalize( lightDir + viewDir );
		float dotNL = saturate( dot( normal, lightDir ) );
		float dotNV = saturate( dot( normal, viewDir ) );
		float dotNH = saturate( dot( normal, halfDir ) );
		float dotVH = saturate( dot( viewDir, halfDir ) );
		vec3 F = F_Schlick( f0, f90, dotVH );
		float V = V_GGX_SmithCorrelated( alpha, dotNL, dotNV );
		float D = D_GGX( alpha, dotNH );
		return F * ( V * D );
	}
#endif
vec3 BRDF_GGX( const in vec3 lightDir, const in vec3 viewDir, const in vec3 normal, const in PhysicalMaterial material ) {
	vec3 f0 = material.specularColor;
	float f90 = material.specularF90;
	float roughness = material.roughness;
	float alpha = pow2( roughness );
	vec3 halfDir = normalize( lightDir + viewDir );
	float dotNL = saturate( dot( normal, lightDir ) );
	float dotNV = saturate( dot( normal, viewDir ) );
	float dotNH = saturate( dot( normal, halfDir ) );
	float dotVH = saturate( dot( viewDir, halfDir ) );
	vec3 F = F_Schlick( f0, f90, dotVH );
	#ifdef USE_IRIDESCENCE
		F = mix( F, material.iridescenceFresnel, material.iridescence );
	#endif
	#ifdef USE_ANISOTROPY
		float dotTL = dot( material.anisotropyT, lightDir );
		float dotTV = dot( material.anisotropyT, viewDir );
		float dotTH = dot( material.anisotropyT, halfDir );
		float dotBL = dot( material.anisotropyB, lightDir );
		float dotBV = dot( material.anisotropyB, viewDir );
		float dotBH = dot( material.anisotropyB, halfDir );
		float V = V_GGX_SmithCorrelated_Anisotropic( material.alphaT, alpha, dotTV, dotBV, dotTL, dotBL, dotNV, dotNL );
		float D = D_GGX_Anisotropic( material.alphaT, alpha, dotNH, dotTH, dotBH );
	#else
		float V = V_GGX_SmithCorrelated( alpha, dotNL, dotNV );
		float D = D_GGX( alpha, dotNH );
	#endif
	return F * ( V * D );
}
vec2 LTC_Uv( const in vec3 N, const in vec3 V, const in float roughness ) {
	const float LUT_SIZE = 64.0;
	const float LUT_SCALE = ( LUT_SIZE - 1.0 ) / LUT_SIZE;
	const float LUT_BIAS = 0.5 / LUT_SIZE;
	float dotNV = saturate( dot( N, V ) );
	vec2 uv = vec2( roughness, sqrt( 1.0 - dotNV ) );
	uv = uv * LUT_SCALE + LUT_BIAS;
	return uv;
}
float LTC_ClippedSphereFormFactor( const in vec3 f ) {
	float l = length( f );
	return max( ( l * l + f.z ) / ( l + 1.0 ), 0.0 );
}
vec3 LTC_EdgeVectorFormFactor( const in vec3 v1, const in vec3 v2 ) {
	float x = dot( v1, v2 );
	float y = abs( x );
	float a = 0.8543985 + ( 0.4965155 + 0.0145206 * y ) * y;
	float b = 3.4175940 + ( 4.1616724 + y ) * y;
	float v = a / b;
	float theta_sintheta = ( x > 0.0 ) ? v : 0.5 * inversesqrt( max( 1.0 - x * x, 1e-7 ) ) - v;
	return cross( v1, v2 ) * theta_sintheta;
}
vec3 LTC_Evaluate( const in vec3 N, const in vec3 V, const in vec3 P, const in mat3 mInv, const in vec3 rectCoords[ 4 ] ) {
	vec3 v1 = rectCoords[ 1 ] - rectCoords[ 0 ];
	vec3 v2 = rectCoords[ 3 ] - rectCoords[ 0 ];
	vec3 lightNormal = cross( v1, v2 );
	if( dot( lightNormal, P - rectCoords[ 0 ] ) < 0.0 ) return vec3( 0.0 );
	vec3 T1, T2;
	T1 = normalize( V - N * dot( V, N ) );
	T2 = - cross( N, T1 );
	mat3 mat = mInv * transposeMat3( mat3( T1, T2, N ) );
	vec3 coords[ 4 ];
	coords[ 0 ] = mat * ( rectCoords[ 0 ] - P );
	coords[ 1 ] = mat * ( rectCoords[ 1 ] - P );
	coords[ 2 ] = mat * ( rectCoords[ 2 ] - P );
	coords[ 3 ] = mat * ( rectCoords[ 3 ] - P );
	coords[ 0 ] = normalize( coords[ 0 ] );
	coords[ 1 ] = normalize( coords[ 1 ] );
	coords[ 2 ] = normalize( coords[ 2 ] );
	coords[ 3 ] = normalize( coords[ 3 ] );
	vec3 vectorFormFactor = vec3( 0.0 );
	vectorFormFactor += LTC_EdgeVectorFormFactor( coords[ 0 ], coords[ 1 ] );
	vectorFormFactor += LTC_EdgeVectorFormFactor( coords[ 1 ], coords[ 2 ] );
	vectorFormFactor += LTC_EdgeVectorFormFactor( coords[ 2 ], coords[ 3 ] );
	vectorFormFactor += LTC_EdgeVectorFormFactor( coords[ 3 ], coords[ 0 ] );
	float result = LTC_ClippedSphereFormFactor( vectorFormFactor );
	return vec3( result );
}
#if defined( USE_SHEEN )
float D_Charlie( float roughness, float dotNH ) {
	float alpha = pow2( roughness );
	float invAlpha = 1.0 / alpha;
	float cos2h = dotNH * dotNH;
	float sin2h = max( 1.0 - cos2h, 0.0078125 );
	return ( 2.0 + invAlpha ) * pow( sin2h, invAlpha * 0.5 ) / ( 2.0 * PI );
}
float V_Neubelt( float dotNV, float dotNL ) {
	return saturate( 1.0 / ( 4.0 * ( dotNL + dotNV - dotNL * dotNV ) ) );
}
vec3 BRDF_Sheen( const in vec3 lightDir, const in vec3 viewDir, const in vec3 normal, vec3 sheenColor, const in float sheenRoughness ) {
	vec3 halfDir = normalize( lightDir + viewDir );
	float dotNL = saturate( dot( normal, lightDir ) );
	float dotNV = saturate( dot( normal, viewDir ) );
	float dotNH = saturate( dot( normal, halfDir ) );
	float D = D_Charlie( sheenRoughness, dotNH );
	float V = V_Neubelt( dotNV, dotNL );
	return sheenColor * ( D * V );
}
#endif
float IBLSheenBRDF( const in vec3 normal, const in vec3 viewDir, const in float roughness ) {
	float dotNV = saturate( dot( normal, viewDir ) );
	float r2 = roughness * roughness;
	float a = roughness < 0.25 ? -339.2 * r2 + 161.4 * roughness - 25.9 : -8.48 * r2 + 14.3 * roughness - 9.95;
	float b = roughness < 0.25 ? 44.0 * r2 - 23.7 * roughness + 3.26 : 1.97 * r2 - 3.27 * roughness + 0.72;
	float DG = exp( a * dotNV + b ) + ( roughness < 0.25 ? 0.0 : 0.1 * ( roughness - 0.25 ) );
	return saturate( DG * RECIPROCAL_PI );
}
vec2 DFGApprox( const in vec3 normal, const in vec3 viewDir, const in float roughness ) {
	float dotNV = saturate( dot( normal, viewDir ) );
	const vec4 c0 = vec4( - 1, - 0.0275, - 0.572, 0.022 );
	const vec4 c1 = vec4( 1, 0.0425, 1.04, - 0.04 );
	vec4 r = roughness * c0 + c1;
	float a004 = min( r.x * r.x, exp2( - 9.28 * dotNV ) ) * r.x + r.y;
	vec2 fab = vec2( - 1.04, 1.04 ) * a004 + r.zw;
	return fab;
}
vec3 EnvironmentBRDF( const in vec3 normal, const in vec3 viewDir, const in vec3 specularColor, const in float specularF90, const in float roughness ) {
	vec2 fab = DFGApprox( normal, viewDir, roughness );
	return specularColor * fab.x + specularF90 * fab.y;
}
#ifdef USE_IRIDESCENCE
void computeMultiscatteringIridescence( const in vec3 normal, const in vec3 viewDir, const in vec3 specularColor, const in float specularF90, const in float iridescence, const in vec3 iridescenceF0, const in float roughness, inout vec3 singleScatter, inout vec3 multiScatter ) {
#else
void computeMultiscattering( const in vec3 normal, const in vec3 viewDir, const in vec3 specularColor, const in float specularF90, const in float roughness, inout vec3 singleScatter, inout vec3 multiScatter ) {
#endif
	vec2 fab = DFGApprox( normal, viewDir, roughness );
	#ifdef USE_IRIDESCENCE
		vec3 Fr = mix( specularColor, iridescenceF0, iridescence );
	#else
		vec3 Fr = specularColor;
	#endif
	vec3 FssEss = Fr * fab.x + specularF90 * fab.y;
	float Ess = fab.x + fab.y;
	float Ems = 1.0 - Ess;
	vec3 Favg = Fr + ( 1.0 - Fr ) * 0.047619;	vec3 Fms = FssEss * Favg / ( 1.0 - Ems * Favg );
	singleScatter += FssEss;
	multiScatter += Fms * Ems;
}
#if NUM_RECT_AREA_LIGHTS > 0
	void RE_Direct_RectArea_Physical( const in RectAreaLight rectAreaLight, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in PhysicalMaterial material, inout ReflectedLight reflectedLight ) {
		vec3 normal = geometryNormal;
		vec3 viewDir = geometryViewDir;
		vec3 position = geometryPosition;
		vec3 lightPos = rectAreaLight.position;
		vec3 halfWidth = rectAreaLight.halfWidth;
		vec3 halfHeight = rectAreaLight.halfHeight;
		vec3 lightColor = rectAreaLight.color;
		float roughness = material.roughness;
		vec3 rectCoords[ 4 ];
		rectCoords[ 0 ] = lightPos + halfWidth - halfHeight;		rectCoords[ 1 ] = lightPos - halfWidth - halfHeight;
		rectCoords[ 2 ] = lightPos - halfWidth + halfHeight;
		rectCoords[ 3 ] = lightPos + halfWidth + halfHeight;
		vec2 uv = LTC_Uv( normal, viewDir, roughness );
		vec4 t1 = texture2D( ltc_1, uv );
		vec4 t2 = texture2D( ltc_2, uv );
		mat3 mInv = mat3(
			vec3( t1.x, 0, t1.y ),
			vec3(    0, 1,    0 ),
			vec3( t1.z, 0, t1.w )
		);
		vec3 fresnel = ( material.specularColor * t2.x + ( vec3( 1.0 ) - material.specularColor ) * t2.y );
		reflectedLight.directSpecular += lightColor * fresnel * LTC_Evaluate( normal, viewDir, position, mInv, rectCoords );
		reflectedLight.directDiffuse += lightColor * material.diffuseColor * LTC_Evaluate( normal, viewDir, position, mat3( 1.0 ), rectCoords );
	}
#endif
void RE_Direct_Physical( const in IncidentLight directLight, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in PhysicalMaterial material, inout ReflectedLight reflectedLight ) {
	float dotNL = saturate( dot( geometryNormal, directLight.direction ) );
	vec3 irradiance = dotNL * directLight.color;
	#ifdef USE_CLEARCOAT
		float dotNLcc = saturate( dot( geometryClearcoatNormal, directLight.direction ) );
		vec3 ccIrradiance = dotNLcc * directLight.color;
		clearcoatSpecularDirect += ccIrradiance * BRDF_GGX_Clearcoat( directLight.direction, geometryViewDir, geometryClearcoatNormal, material );
	#endif
	#ifdef USE_SHEEN
		sheenSpecularDirect += irradiance * BRDF_Sheen( directLight.direction, geometryViewDir, geometryNormal, material.sheenColor, material.sheenRoughness );
	#endif
	reflectedLight.directSpecular += irradiance * BRDF_GGX( directLight.direction, geometryViewDir, geometryNormal, material );
	reflectedLight.directDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
}
void RE_IndirectDiffuse_Physical( const in vec3 irradiance, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in PhysicalMaterial material, inout ReflectedLight reflectedLight ) {
	reflectedLight.indirectDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
}
void RE_IndirectSpecular_Physical( const in vec3 radiance, const in vec3 irradiance, const in vec3 clearcoatRadiance, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in PhysicalMaterial material, inout ReflectedLight reflectedLight) {
	#ifdef USE_CLEARCOAT
		clearcoatSpecularIndirect += clearcoatRadiance * EnvironmentBRDF( geometryClearcoatNormal, geometryViewDir, material.clearcoatF0, material.clearcoatF90, material.clearcoatRoughness );
	#endif
	#ifdef USE_SHEEN
		sheenSpecularIndirect += irradiance * material.sheenColor * IBLSheenBRDF( geometryNormal, geometryViewDir, material.sheenRoughness );
	#endif
	vec3 singleScattering = vec3( 0.0 );
	vec3 multiScattering = vec3( 0.0 );
	vec3 cosineWeightedIrradiance = irradiance * RECIPROCAL_PI;
	#ifdef USE_IRIDESCENCE
		computeMultiscatteringIridescence( geometryNormal, geometryViewDir, material.specularColor, material.specularF90, material.iridescence, material.iridescenceFresnel, material.roughness, singleScattering, multiScattering );
	#else
		computeMultiscattering( geometryNormal, geometryViewDir, material.specularColor, material.specularF90, material.roughness, singleScattering, multiScattering );
	#endif
	vec3 totalScattering = singleScattering + multiScattering;
	vec3 diffuse = material.diffuseColor * ( 1.0 - max( max( totalScattering.r, totalScattering.g ), totalScattering.b ) );
	reflectedLight.indirectSpecular += radiance * singleScattering;
	reflectedLight.indirectSpecular += multiScattering * cosineWeightedIrradiance;
	reflectedLight.indirectDiffuse += diffuse * cosineWeightedIrradiance;
}
#define RE_Direct				RE_Direct_Physical
#define RE_Direct_RectArea		RE_Direct_RectArea_Physical
#define RE_IndirectDiffuse		RE_IndirectDiffuse_Physical
#define RE_IndirectSpecular		RE_IndirectSpecular_Physical
float computeSpecularOcclusion( const in float dotNV, const in float ambientOcclusion, const in float roughness ) {
	return saturate( pow( dotNV + ambientOcclusion, exp2( - 16.0 * roughness - 1.0 ) ) - 1.0 + ambientOcclusion );
}`,Om=`
vec3 geometryPosition = - vViewPosition;
vec3 geometryNormal = normal;
vec3 geometryViewDir = ( isOrthographic ) ? vec3( 0, 0, 1 ) : normalize( vViewPosition );
vec3 geometryClearcoatNormal = vec3( 0.0 );
#ifdef USE_CLEARCOAT
	geometryClearcoatNormal = clearcoatNormal;
#endif
#ifdef USE_IRIDESCENCE
	float dotNVi = saturate( dot( normal, geometryViewDir ) );
	if ( material.iridescenceThickness == 0.0 ) {
		material.iridescence = 0.0;
	} else {
		material.iridescence = saturate( material.iridescence );
	}
	if ( material.iridescence > 0.0 ) {
		material.iridescenceFresnel = evalIridescence( 1.0, material.iridescenceIOR, dotNVi, material.iridescenceThickness, material.specularColor );
		material.iridescenceF0 = Schlick_to_F0( material.iridescenceFresnel, 1.0, dotNVi );
	}
#endif
IncidentLight directLight;
#if ( NUM_POINT_LIGHTS > 0 ) && defined( RE_Direct )
	PointLight pointLight;
	#if defined( USE_SHADOWMAP ) && NUM_POINT_LIGHT_SHADOWS > 0
	PointLightShadow pointLightShadow;
	#endif
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_POINT_LIGHTS; i ++ ) {
		pointLight = pointLights[ i ];
		getPointLightInfo( pointLight, geometryPosition, directLight );
		#if defined( USE_SHADOWMAP ) && ( UNROLLED_LOOP_INDEX < NUM_POINT_LIGHT_SHADOWS )
		pointLightShadow = pointLightShadows[ i ];
		directLight.color *= ( directLight.visible && receiveShadow ) ? getPointShadow( pointShadowMap[ i ], pointLightShadow.shadowMapSize, pointLightShadow.shadowIntensity, pointLightShadow.shadowBias, pointLightShadow.shadowRadius, vPointShadowCoord[ i ], pointLightShadow.shadowCameraNear, pointLightShadow.shadowCameraFar ) : 1.0;
		#endif
		RE_Direct( directLight, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
	}
	#pragma unroll_loop_end
#endif
#if ( NUM_SPOT_LIGHTS > 0 ) && defined( RE_Direct )
	SpotLight spotLight;
	vec4 spotColor;
	vec3 spotLightCoord;
	bool inSpotLightMap;
	#if defined( USE_SHADOWMAP ) && NUM_SPOT_LIGHT_SHADOWS > 0
	SpotLightShadow spotLightShadow;
	#endif
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_SPOT_LIGHTS; i ++ ) {
		spotLight = spotLights[ i ];
		getSpotLightInfo( spotLight, geometryPosition, directLight );
		#if ( UNROLLED_LOOP_INDEX < NUM_SPOT_LIGHT_SHADOWS_WITH_MAPS )
		#define SPOT_LIGHT_MAP_INDEX UNROLLED_LOOP_INDEX
		#elif ( UNROLLED_LOOP_INDEX < NUM_SPOT_LIGHT_SHADOWS )
		#define SPOT_LIGHT_MAP_INDEX NUM_SPOT_LIGHT_MAPS
		#else
		#define SPOT_LIGHT_MAP_INDEX ( UNROLLED_LOOP_INDEX - NUM_SPOT_LIGHT_SHADOWS + NUM_SPOT_LIGHT_SHADOWS_WITH_MAPS )
		#endif
		#if ( SPOT_LIGHT_MAP_INDEX < NUM_SPOT_LIGHT_MAPS )
			spotLightCoord = vSpotLightCoord[ i ].xyz / vSpotLightCoord[ i ].w;
			inSpotLightMap = all( lessThan( abs( spotLightCoord * 2. - 1. ), vec3( 1.0 ) ) );
			spotColor = texture2D( spotLightMap[ SPOT_LIGHT_MAP_INDEX ], spotLightCoord.xy );
			directLight.color = inSpotLightMap ? directLight.color * spotColor.rgb : directLight.color;
		#endif
		#undef SPOT_LIGHT_MAP_INDEX
		#if defined( USE_SHADOWMAP ) && ( UNROLLED_LOOP_INDEX < NUM_SPOT_LIGHT_SHADOWS )
		spotLightShadow = spotLightShadows[ i ];
		directLight.color *= ( directLight.visible && receiveShadow ) ? getShadow( spotShadowMap[ i ], spotLightShadow.shadowMapSize, spotLightShadow.shadowIntensity, spotLightShadow.shadowBias, spotLightShadow.shadowRadius, vSpotLightCoord[ i ] ) : 1.0;
		#endif
		RE_Direct( directLight, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
	}
	#pragma unroll_loop_end
#endif
#if ( NUM_DIR_LIGHTS > 0 ) && defined( RE_Direct )
	DirectionalLight directionalLight;
	#if defined( USE_SHADOWMAP ) && NUM_DIR_LIGHT_SHADOWS > 0
	DirectionalLightShadow directionalLightShadow;
	#endif
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_DIR_LIGHTS; i ++ ) {
		directionalLight = directionalLights[ i ];
		getDirectionalLightInfo( directionalLight, directLight );
		#if defined( USE_SHADOWMAP ) && ( UNROLLED_LOOP_INDEX < NUM_DIR_LIGHT_SHADOWS )
		directionalLightShadow = directionalLightShadows[ i ];
		directLight.color *= ( directLight.visible && receiveShadow ) ? getShadow( directionalShadowMap[ i ], directionalLightShadow.shadowMapSize, directionalLightShadow.shadowIntensity, directionalLightShadow.shadowBias, directionalLightShadow.shadowRadius, vDirectionalShadowCoord[ i ] ) : 1.0;
		#endif
		RE_Direct( directLight, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
	}
	#pragma unroll_loop_end
#endif
#if ( NUM_RECT_AREA_LIGHTS > 0 ) && defined( RE_Direct_RectArea )
	RectAreaLight rectAreaLight;
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_RECT_AREA_LIGHTS; i ++ ) {
		rectAreaLight = rectAreaLights[ i ];
		RE_Direct_RectArea( rectAreaLight, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
	}
	#pragma unroll_loop_end
#endif
#if defined( RE_IndirectDiffuse )
	vec3 iblIrradiance = vec3( 0.0 );
	vec3 irradiance = getAmbientLightIrradiance( ambientLightColor );
	#if defined( USE_LIGHT_PROBES )
		irradiance += getLightProbeIrradiance( lightProbe, geometryNormal );
	#endif
	#if ( NUM_HEMI_LIGHTS > 0 )
		#pragma unroll_loop_start
		for ( int i = 0; i < NUM_HEMI_LIGHTS; i ++ ) {
			irradiance += getHemisphereLightIrradiance( hemisphereLights[ i ], geometryNormal );
		}
		#pragma unroll_loop_end
	#endif
#endif
#if defined( RE_IndirectSpecular )
	vec3 radiance = vec3( 0.0 );
	vec3 clearcoatRadiance = vec3( 0.0 );
#endif`,zm=`#if defined( RE_IndirectDiffuse )
	#ifdef USE_LIGHTMAP
		vec4 lightMapTexel = texture2D( lightMap, vLightMapUv );
		vec3 lightMapIrradiance = lightMapTexel.rgb * lightMapIntensity;
		irradiance += lightMapIrradiance;
	#endif
	#if defined( USE_ENVMAP ) && defined( STANDARD ) && defined( ENVMAP_TYPE_CUBE_UV )
		iblIrradiance += getIBLIrradiance( geometryNormal );
	#endif
#endif
#if defined( USE_ENVMAP ) && defined( RE_IndirectSpecular )
	#ifdef USE_ANISOTROPY
		radiance += getIBLAnisotropyRadiance( geometryViewDir, geometryNormal, material.roughness, material.anisotropyB, material.anisotropy );
	#else
		radiance += getIBLRadiance( geometryViewDir, geometryNormal, material.roughness );
	#endif
	#ifdef USE_CLEARCOAT
		clearcoatRadiance += getIBLRadiance( geometryViewDir, geometryClearcoatNormal, material.clearcoatRoughness );
	#endif
#endif`,Bm=`#if defined( RE_IndirectDiffuse )
	RE_IndirectDiffuse( irradiance, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
#endif
#if defined( RE_IndirectSpecular )
	RE_IndirectSpecular( radiance, iblIrradiance, clearcoatRadiance, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
#endif`,Gm=`#if defined( USE_LOGDEPTHBUF )
	gl_FragDepth = vIsPerspective == 0.0 ? gl_FragCoord.z : log2( vFragDepth ) * logDepthBufFC * 0.5;
#endif`,Hm=`#if defined( USE_LOGDEPTHBUF )
	uniform float logDepthBufFC;
	varying float vFragDepth;
	varying float vIsPerspective;
#endif`,Vm=`#ifdef USE_LOGDEPTHBUF
	varying float vFragDepth;
	varying float vIsPerspective;
#endif`,Wm=`#ifdef USE_LOGDEPTHBUF
	vFragDepth = 1.0 + gl_Position.w;
	vIsPerspective = float( isPerspectiveMatrix( projectionMatrix ) );
#endif`,qm=`#ifdef USE_MAP
	vec4 sampledDiffuseColor = texture2D( map, vMapUv );
	#ifdef DECODE_VIDEO_TEXTURE
		sampledDiffuseColor = sRGBTransferEOTF( sampledDiffuseColor );
	#endif
	diffuseColor *= sampledDiffuseColor;
#endif`,Xm=`#ifdef USE_MAP
	uniform sampler2D map;
#endif`,Km=`#if defined( USE_MAP ) || defined( USE_ALPHAMAP )
	#if defined( USE_POINTS_UV )
		vec2 uv = vUv;
	#else
		vec2 uv = ( uvTransform * vec3( gl_PointCoord.x, 1.0 - gl_PointCoord.y, 1 ) ).xy;
	#endif
#endif
#ifdef USE_MAP
	diffuseColor *= texture2D( map, uv );
#endif
#ifdef USE_ALPHAMAP
	diffuseColor.a *= texture2D( alphaMap, uv ).g;
#endif`,Jm=`#if defined( USE_POINTS_UV )
	varying vec2 vUv;
#else
	#if defined( USE_MAP ) || defined( USE_ALPHAMAP )
		uniform mat3 uvTransform;
	#endif
#endif
#ifdef USE_MAP
	uniform sampler2D map;
#endif
#ifdef USE_ALPHAMAP
	uniform sampler2D alphaMap;
#endif`,Ym=`float metalnessFactor = metalness;
#ifdef USE_METALNESSMAP
	vec4 texelMetalness = texture2D( metalnessMap, vMetalnessMapUv );
	metalnessFactor *= texelMetalness.b;
#endif`,Zm=`#ifdef USE_METALNESSMAP
	uniform sampler2D metalnessMap;
#endif`,Qm=`#ifdef USE_INSTANCING_MORPH
	float morphTargetInfluences[ MORPHTARGETS_COUNT ];
	float morphTargetBaseInfluence = texelFetch( morphTexture, ivec2( 0, gl_InstanceID ), 0 ).r;
	for ( int i = 0; i < MORPHTARGETS_COUNT; i ++ ) {
		morphTargetInfluences[i] =  texelFetch( morphTexture, ivec2( i + 1, gl_InstanceID ), 0 ).r;
	}
#endif`,$m=`#if defined( USE_MORPHCOLORS )
	vColor *= morphTargetBaseInfluence;
	for ( int i = 0; i < MORPHTARGETS_COUNT; i ++ ) {
		#if defined( USE_COLOR_ALPHA )
			if ( morphTargetInfluences[ i ] != 0.0 ) vColor += getMorph( gl_VertexID, i, 2 ) * morphTargetInfluences[ i ];
		#elif defined( USE_COLOR )
			if ( morphTargetInfluences[ i ] != 0.0 ) vColor += getMorph( gl_VertexID, i, 2 ).rgb * morphTargetInfluences[ i ];
		#endif
	}
#endif`,ep=`#ifdef USE_MORPHNORMALS
	objectNormal *= morphTargetBaseInfluence;
	for ( int i = 0; i < MORPHTARGETS_COUNT; i ++ ) {
		if ( morphTargetInfluences[ i ] != 0.0 ) objectNormal += getMorph( gl_VertexID, i, 1 ).xyz * morphTargetInfluences[ i ];
	}
#endif`,tp=`#ifdef USE_MORPHTARGETS
	#ifndef USE_INSTANCING_MORPH
		uniform float morphTargetBaseInfluence;
		uniform float morphTargetInfluences[ MORPHTARGETS_COUNT ];
	#endif
	uniform sampler2DArray morphTargetsTexture;
	uniform ivec2 morphTargetsTextureSize;
	vec4 getMorph( const in int vertexIndex, const in int morphTargetIndex, const in int offset ) {
		int texelIndex = vertexIndex * MORPHTARGETS_TEXTURE_STRIDE + offset;
		int y = texelIndex / morphTargetsTextureSize.x;
		int x = texelIndex - y * morphTargetsTextureSize.x;
		ivec3 morphUV = ivec3( x, y, morphTargetIndex );
		return texelFetch( morphTargetsTexture, morphUV, 0 );
	}
#endif`,ap=`#ifdef USE_MORPHTARGETS
	transformed *= morphTargetBaseInfluence;
	for ( int i = 0; i < MORPHTARGETS_COUNT; i ++ ) {
		if ( morphTargetInfluences[ i ] != 0.0 ) transformed += getMorph( gl_VertexID, i, 0 ).xyz * morphTargetInfluences[ i ];
	}
#endif`,np=`float faceDirection = gl_FrontFacing ? 1.0 : - 1.0;
#ifdef FLAT_SHADED
	vec3 fdx = dFdx( vViewPosition );
	vec3 fdy = dFdy( vViewPosition );
	vec3 normal = normalize( cross( fdx, fdy ) );
#else
	vec3 normal = normalize( vNormal );
	#ifdef DOUBLE_SIDED
		normal *= faceDirection;
	#endif
#endif
#if defined( USE_NORMALMAP_TANGENTSPACE ) || defined( USE_CLEARCOAT_NORMALMAP ) || defined( USE_ANISOTROPY )
	#ifdef USE_TANGENT
		mat3 tbn = mat3( normalize( vTangent ), normalize( vBitangent ), normal );
	#else
		mat3 tbn = getTangentFrame( - vViewPosition, normal,
		#if defined( USE_NORMALMAP )
			vNormalMapUv
		#elif defined( USE_CLEARCOAT_NORMALMAP )
			vClearcoatNormalMapUv
		#else
			vUv
		#endif
		);
	#endif
	#if defined( DOUBLE_SIDED ) && ! defined( FLAT_SHADED )
		tbn[0] *= faceDirection;
		tbn[1] *= faceDirection;
	#endif
#endif
#ifdef USE_CLEARCOAT_NORMALMAP
	#ifdef USE_TANGENT
		mat3 tbn2 = mat3( normalize( vTangent ), normalize( vBitangent ), normal );
	#else
		mat3 tbn2 = getTangentFrame( - vViewPosition, normal, vClearcoatNormalMapUv );
	#endif
	#if defined( DOUBLE_SIDED ) && ! defined( FLAT_SHADED )
		tbn2[0] *= faceDirection;
		tbn2[1] *= faceDirection;
	#endif
#endif
vec3 nonPerturbedNormal = normal;`,ip=`#ifdef USE_NORMALMAP_OBJECTSPACE
	normal = texture2D( normalMap, vNormalMapUv ).xyz * 2.0 - 1.0;
	#ifdef FLIP_SIDED
		normal = - normal;
	#endif
	#ifdef DOUBLE_SIDED
		normal = normal * faceDirection;
	#endif
	normal = normalize( normalMatrix * normal );
#elif defined( USE_NORMALMAP_TANGENTSPACE )
	vec3 mapN = texture2D( normalMap, vNormalMapUv ).xyz * 2.0 - 1.0;
	mapN.xy *= normalScale;
	normal = normalize( tbn * mapN );
#elif defined( USE_BUMPMAP )
	normal = perturbNormalArb( - vViewPosition, normal, dHdxy_fwd(), faceDirection );
#endif`,rp=`#ifndef FLAT_SHADED
	varying vec3 vNormal;
	#ifdef USE_TANGENT
		varying vec3 vTangent;
		varying vec3 vBitangent;
	#endif
#endif`,sp=`#ifndef FLAT_SHADED
	varying vec3 vNormal;
	#ifdef USE_TANGENT
		varying vec3 vTangent;
		varying vec3 vBitangent;
	#endif
#endif`,op=`#ifndef FLAT_SHADED
	vNormal = normalize( transformedNormal );
	#ifdef USE_TANGENT
		vTangent = normalize( transformedTangent );
		vBitangent = normalize( cross( vNormal, vTangent ) * tangent.w );
	#endif
#endif`,cp=`#ifdef USE_NORMALMAP
	uniform sampler2D normalMap;
	uniform vec2 normalScale;
#endif
#ifdef USE_NORMALMAP_OBJECTSPACE
	uniform mat3 normalMatrix;
#endif
#if ! defined ( USE_TANGENT ) && ( defined ( USE_NORMALMAP_TANGENTSPACE ) || defined ( USE_CLEARCOAT_NORMALMAP ) || defined( USE_ANISOTROPY ) )
	mat3 getTangentFrame( vec3 eye_pos, vec3 surf_norm, vec2 uv ) {
		vec3 q0 = dFdx( eye_pos.xyz );
		vec3 q1 = dFdy( eye_pos.xyz );
		vec2 st0 = dFdx( uv.st );
		vec2 st1 = dFdy( uv.st );
		vec3 N = surf_norm;
		vec3 q1perp = cross( q1, N );
		vec3 q0perp = cross( N, q0 );
		vec3 T = q1perp * st0.x + q0perp * st1.x;
		vec3 B = q1perp * st0.y + q0perp * st1.y;
		float det = max( dot( T, T ), dot( B, B ) );
		float scale = ( det == 0.0 ) ? 0.0 : inversesqrt( det );
		return mat3( T * scale, B * scale, N );
	}
#endif`,hp=`#ifdef USE_CLEARCOAT
	vec3 clearcoatNormal = nonPerturbedNormal;
#endif`,lp=`#ifdef USE_CLEARCOAT_NORMALMAP
	vec3 clearcoatMapN = texture2D( clearcoatNormalMap, vClearcoatNormalMapUv ).xyz * 2.0 - 1.0;
	clearcoatMapN.xy *= clearcoatNormalScale;
	clearcoatNormal = normalize( tbn2 * clearcoatMapN );
#endif`,dp=`#ifdef USE_CLEARCOATMAP
	uniform sampler2D clearcoatMap;
#endif
#ifdef USE_CLEARCOAT_NORMALMAP
	uniform sampler2D clearcoatNormalMap;
	uniform vec2 clearcoatNormalScale;
#endif
#ifdef USE_CLEARCOAT_ROUGHNESSMAP
	uniform sampler2D clearcoatRoughnessMap;
#endif`,fp=`#ifdef USE_IRIDESCENCEMAP
	uniform sampler2D iridescenceMap;
#endif
#ifdef USE_IRIDESCENCE_THICKNESSMAP
	uniform sampler2D iridescenceThicknessMap;
#endif`,up=`#ifdef OPAQUE
diffuseColor.a = 1.0;
#endif
#ifdef USE_TRANSMISSION
diffuseColor.a *= material.transmissionAlpha;
#endif
gl_FragColor = vec4( outgoingLight, diffuseColor.a );`,bp=`vec3 packNormalToRGB( const in vec3 normal ) {
	return normalize( normal ) * 0.5 + 0.5;
}
vec3 unpackRGBToNormal( const in vec3 rgb ) {
	return 2.0 * rgb.xyz - 1.0;
}
const float PackUpscale = 256. / 255.;const float UnpackDownscale = 255. / 256.;const float ShiftRight8 = 1. / 256.;
const float Inv255 = 1. / 255.;
const vec4 PackFactors = vec4( 1.0, 256.0, 256.0 * 256.0, 256.0 * 256.0 * 256.0 );
const vec2 UnpackFactors2 = vec2( UnpackDownscale, 1.0 / PackFactors.g );
const vec3 UnpackFactors3 = vec3( UnpackDownscale / PackFactors.rg, 1.0 / PackFactors.b );
const vec4 UnpackFactors4 = vec4( UnpackDownscale / PackFactors.rgb, 1.0 / PackFactors.a );
vec4 packDepthToRGBA( const in float v ) {
	if( v <= 0.0 )
		return vec4( 0., 0., 0., 0. );
	if( v >= 1.0 )
		return vec4( 1., 1., 1., 1. );
	float vuf;
	float af = modf( v * PackFactors.a, vuf );
	float bf = modf( vuf * ShiftRight8, vuf );
	float gf = modf( vuf * ShiftRight8, vuf );
	return vec4( vuf * Inv255, gf * PackUpscale, bf * PackUpscale, af );
}
vec3 packDepthToRGB( const in float v ) {
	if( v <= 0.0 )
		return vec3( 0., 0., 0. );
	if( v >= 1.0 )
		return vec3( 1., 1., 1. );
	float vuf;
	float bf = modf( v * PackFactors.b, vuf );
	float gf = modf( vuf * ShiftRight8, vuf );
	return vec3( vuf * Inv255, gf * PackUpscale, bf );
}
vec2 packDepthToRG( const in float v ) {
	if( v <= 0.0 )
		return vec2( 0., 0. );
	if( v >= 1.0 )
		return vec2( 1., 1. );
	float vuf;
	float gf = modf( v * 256., vuf );
	return vec2( vuf * Inv255, gf );
}
float unpackRGBAToDepth( const in vec4 v ) {
	return dot( v, UnpackFactors4 );
}
float unpackRGBToDepth( const in vec3 v ) {
	return dot( v, UnpackFactors3 );
}
float unpackRGToDepth( const in vec2 v ) {
	return v.r * UnpackFactors2.r + v.g * UnpackFactors2.g;
}
vec4 pack2HalfToRGBA( const in vec2 v ) {
	vec4 r = vec4( v.x, fract( v.x * 255.0 ), v.y, fract( v.y * 255.0 ) );
	return vec4( r.x - r.y / 255.0, r.y, r.z - r.w / 255.0, r.w );
}
vec2 unpackRGBATo2Half( const in vec4 v ) {
	return vec2( v.x + ( v.y / 255.0 ), v.z + ( v.w / 255.0 ) );
}
float viewZToOrthographicDepth( const in float viewZ, const in float near, const in float far ) {
	return ( viewZ + near ) / ( near - far );
}
float orthographicDepthToViewZ( const in float depth, const in float near, const in float far ) {
	return depth * ( near - far ) - near;
}
float viewZToPerspectiveDepth( const in float viewZ, const in float near, const in float far ) {
	return ( ( near + viewZ ) * far ) / ( ( far - near ) * viewZ );
}
float perspectiveDepthToViewZ( const in float depth, const in float near, const in float far ) {
	return ( near * far ) / ( ( far - near ) * depth - far );
}`,mp=`#ifdef PREMULTIPLIED_ALPHA
	gl_FragColor.rgb *= gl_FragColor.a;
#endif`,pp=`vec4 mvPosition = vec4( transformed, 1.0 );
#ifdef USE_BATCHING
	mvPosition = batchingMatrix * mvPosition;
#endif
#ifdef USE_INSTANCING
	mvPosition = instanceMatrix * mvPosition;
#endif
mvPosition = modelViewMatrix * mvPosition;
gl_Position = projectionMatrix * mvPosition;`,gp=`#ifdef DITHERING
	gl_FragColor.rgb = dithering( gl_FragColor.rgb );
#endif`,vp=`#ifdef DITHERING
	vec3 dithering( vec3 color ) {
		float grid_position = rand( gl_FragCoord.xy );
		vec3 dither_shift_RGB = vec3( 0.25 / 255.0, -0.25 / 255.0, 0.25 / 255.0 );
		dither_shift_RGB = mix( 2.0 * dither_shift_RGB, -2.0 * dither_shift_RGB, grid_position );
		return color + dither_shift_RGB;
	}
#endif`,yp=`float roughnessFactor = roughness;
#ifdef USE_ROUGHNESSMAP
	vec4 texelRoughness = texture2D( roughnessMap, vRoughnessMapUv );
	roughnessFactor *= texelRoughness.g;
#endif`,xp=`#ifdef USE_ROUGHNESSMAP
	uniform sampler2D roughnessMap;
#endif`,wp=`#if NUM_SPOT_LIGHT_COORDS > 0
	varying vec4 vSpotLightCoord[ NUM_SPOT_LIGHT_COORDS ];
#endif
#if NUM_SPOT_LIGHT_MAPS > 0
	uniform sampler2D spotLightMap[ NUM_SPOT_LIGHT_MAPS ];
#endif
#ifdef USE_SHADOWMAP
	#if NUM_DIR_LIGHT_SHADOWS > 0
		uniform sampler2D directionalShadowMap[ NUM_DIR_LIGHT_SHADOWS ];
		varying vec4 vDirectionalShadowCoord[ NUM_DIR_LIGHT_SHADOWS ];
		struct DirectionalLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
		};
		uniform DirectionalLightShadow directionalLightShadows[ NUM_DIR_LIGHT_SHADOWS ];
	#endif
	#if NUM_SPOT_LIGHT_SHADOWS > 0
		uniform sampler2D spotShadowMap[ NUM_SPOT_LIGHT_SHADOWS ];
		struct SpotLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
		};
		uniform SpotLightShadow spotLightShadows[ NUM_SPOT_LIGHT_SHADOWS ];
	#endif
	#if NUM_POINT_LIGHT_SHADOWS > 0
		uniform sampler2D pointShadowMap[ NUM_POINT_LIGHT_SHADOWS ];
		varying vec4 vPointShadowCoord[ NUM_POINT_LIGHT_SHADOWS ];
		struct PointLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
			float shadowCameraNear;
			float shadowCameraFar;
		};
		uniform PointLightShadow pointLightShadows[ NUM_POINT_LIGHT_SHADOWS ];
	#endif
	float texture2DCompare( sampler2D depths, vec2 uv, float compare ) {
		return step( compare, unpackRGBAToDepth( texture2D( depths, uv ) ) );
	}
	vec2 texture2DDistribution( sampler2D shadow, vec2 uv ) {
		return unpackRGBATo2Half( texture2D( shadow, uv ) );
	}
	float VSMShadow (sampler2D shadow, vec2 uv, float compare ){
		float occlusion = 1.0;
		vec2 distribution = texture2DDistribution( shadow, uv );
		float hard_shadow = step( compare , distribution.x );
		if (hard_shadow != 1.0 ) {
			float distance = compare - distribution.x ;
			float variance = max( 0.00000, distribution.y * distribution.y );
			float softness_probability = variance / (variance + distance * distance );			softness_probability = clamp( ( softness_probability - 0.3 ) / ( 0.95 - 0.3 ), 0.0, 1.0 );			occlusion = clamp( max( hard_shadow, softness_probability ), 0.0, 1.0 );
		}
		return occlusion;
	}
	float getShadow( sampler2D shadowMap, vec2 shadowMapSize, float shadowIntensity, float shadowBias, float shadowRadius, vec4 shadowCoord ) {
		float shadow = 1.0;
		shadowCoord.xyz /= shadowCoord.w;
		shadowCoord.z += shadowBias;
		bool inFrustum = shadowCoord.x >= 0.0 && shadowCoord.x <= 1.0 && shadowCoord.y >= 0.0 && shadowCoord.y <= 1.0;
		bool frustumTest = inFrustum && shadowCoord.z <= 1.0;
		if ( frustumTest ) {
		#if defined( SHADOWMAP_TYPE_PCF )
			vec2 texelSize = vec2( 1.0 ) / shadowMapSize;
			float dx0 = - texelSize.x * shadowRadius;
			float dy0 = - texelSize.y * shadowRadius;
			float dx1 = + texelSize.x * shadowRadius;
			float dy1 = + texelSize.y * shadowRadius;
			float dx2 = dx0 / 2.0;
			float dy2 = dy0 / 2.0;
			float dx3 = dx1 / 2.0;
			float dy3 = dy1 / 2.0;
			shadow = (
				texture2DCompare( shadowMap, shadowCoord.xy + vec2( dx0, dy0 ), shadowCoord.z ) +
				texture2DCompare( shadowMap, shadowCoord.xy + vec2( 0.0, dy0 ), shadowCoord.z ) +
				texture2DCompare( shadowMap, shadowCoord.xy + vec2( dx1, dy0 ), shadowCoord.z ) +
				texture2DCompare( shadowMap, shadowCoord.xy + vec2( dx2, dy2 ), shadowCoord.z ) +
				texture2DCompare( shadowMap, shadowCoord.xy + vec2( 0.0, dy2 ), shadowCoord.z ) +
				texture2DCompare( shadowMap, shadowCoord.xy + vec2( dx3, dy2 ), shadowCoord.z ) +
				texture2DCompare( shadowMap, shadowCoord.xy + vec2( dx0, 0.0 ), shadowCoord.z ) +
				texture2DCompare( shadowMap, shadowCoord.xy + vec2( dx2, 0.0 ), shadowCoord.z ) +
				texture2DCompare( shadowMap, shadowCoord.xy, shadowCoord.z ) +
				texture2DCompare( shadowMap, shadowCoord.xy + vec2( dx3, 0.0 ), shadowCoord.z ) +
				texture2DCompare( shadowMap, shadowCoord.xy + vec2( dx1, 0.0 ), shadowCoord.z ) +
				texture2DCompare( shadowMap, shadowCoord.xy + vec2( dx2, dy3 ), shadowCoord.z ) +
				texture2DCompare( shadowMap, shadowCoord.xy + vec2( 0.0, dy3 ), shadowCoord.z ) +
				texture2DCompare( shadowMap, shadowCoord.xy + vec2( dx3, dy3 ), shadowCoord.z ) +
				texture2DCompare( shadowMap, shadowCoord.xy + vec2( dx0, dy1 ), shadowCoord.z ) +
				texture2DCompare( shadowMap, shadowCoord.xy + vec2( 0.0, dy1 ), shadowCoord.z ) +
				texture2DCompare( shadowMap, shadowCoord.xy + vec2( dx1, dy1 ), shadowCoord.z )
			) * ( 1.0 / 17.0 );
		#elif defined( SHADOWMAP_TYPE_PCF_SOFT )
			vec2 texelSize = vec2( 1.0 ) / shadowMapSize;
			float dx = texelSize.x;
			float dy = texelSize.y;
			vec2 uv = shadowCoord.xy;
			vec2 f = fract( uv * shadowMapSize + 0.5 );
			uv -= f * texelSize;
			shadow = (
				texture2DCompare( shadowMap, uv, shadowCoord.z ) +
				texture2DCompare( shadowMap, uv + vec2( dx, 0.0 ), shadowCoord.z ) +
				texture2DCompare( shadowMap, uv + vec2( 0.0, dy ), shadowCoord.z ) +
				texture2DCompare( shadowMap, uv + texelSize, shadowCoord.z ) +
				mix( texture2DCompare( shadowMap, uv + vec2( -dx, 0.0 ), shadowCoord.z ),
					 texture2DCompare( shadowMap, uv + vec2( 2.0 * dx, 0.0 ), shadowCoord.z ),
					 f.x ) +
				mix( texture2DCompare( shadowMap, uv + vec2( -dx, dy ), shadowCoord.z ),
					 texture2DCompare( shadowMap, uv + vec2( 2.0 * dx, dy ), shadowCoord.z ),
					 f.x ) +
				mix( texture2DCompare( shadowMap, uv + vec2( 0.0, -dy ), shadowCoord.z ),
					 texture2DCompare( shadowMap, uv + vec2( 0.0, 2.0 * dy ), shadowCoord.z ),
					 f.y ) +
				mix( texture2DCompare( shadowMap, uv + vec2( dx, -dy ), shadowCoord.z ),
					 texture2DCompare( shadowMap, uv + vec2( dx, 2.0 * dy ), shadowCoord.z ),
					 f.y ) +
				mix( mix( texture2DCompare( shadowMap, uv + vec2( -dx, -dy ), shadowCoord.z ),
						  texture2DCompare( shadowMap, uv + vec2( 2.0 * dx, -dy ), shadowCoord.z ),
						  f.x ),
					 mix( texture2DCompare( shadowMap, uv + vec2( -dx, 2.0 * dy ), shadowCoord.z ),
						  texture2DCompare( shadowMap, uv + vec2( 2.0 * dx, 2.0 * dy ), shadowCoord.z ),
						  f.x ),
					 f.y )
			) * ( 1.0 / 9.0 );
		#elif defined( SHADOWMAP_TYPE_VSM )
			shadow = VSMShadow( shadowMap, shadowCoord.xy, shadowCoord.z );
		#else
			shadow = texture2DCompare( shadowMap, shadowCoord.xy, shadowCoord.z );
		#endif
		}
		return mix( 1.0, shadow, shadowIntensity );
	}
	vec2 cubeToUV( vec3 v, float texelSizeY ) {
		vec3 absV = abs( v );
		float scaleToCube = 1.0 / max( absV.x, max( absV.y, absV.z ) );
		absV *= scaleToCube;
		v *= scaleToCube * ( 1.0 - 2.0 * texelSizeY );
		vec2 planar = v.xy;
		float almostATexel = 1.5 * texelSizeY;
		float almostOne = 1.0 - almostATexel;
		if ( absV.z >= almostOne ) {
			if ( v.z > 0.0 )
				planar.x = 4.0 - v.x;
		} else if ( absV.x >= almostOne ) {
			float signX = sign( v.x );
			planar.x = v.z * signX + 2.0 * signX;
		} else if ( absV.y >= almostOne ) {
			float signY = sign( v.y );
			planar.x = v.x + 2.0 * signY + 2.0;
			planar.y = v.z * signY - 2.0;
		}
		return vec2( 0.125, 0.25 ) * planar + vec2( 0.375, 0.75 );
	}
	float getPointShadow( sampler2D shadowMap, vec2 shadowMapSize, float shadowIntensity, float shadowBias, float shadowRadius, vec4 shadowCoord, float shadowCameraNear, float shadowCameraFar ) {
		float shadow = 1.0;
		vec3 lightToPosition = shadowCoord.xyz;
		
		float lightToPositionLength = length( lightToPosition );
		if ( lightToPositionLength - shadowCameraFar <= 0.0 && lightToPositionLength - shadowCameraNear >= 0.0 ) {
			float dp = ( lightToPositionLength - shadowCameraNear ) / ( shadowCameraFar - shadowCameraNear );			dp += shadowBias;
			vec3 bd3D = normalize( lightToPosition );
			vec2 texelSize = vec2( 1.0 ) / ( shadowMapSize * vec2( 4.0, 2.0 ) );
			#if defined( SHADOWMAP_TYPE_PCF ) || defined( SHADOWMAP_TYPE_PCF_SOFT ) || defined( SHADOWMAP_TYPE_VSM )
				vec2 offset = vec2( - 1, 1 ) * shadowRadius * texelSize.y;
				shadow = (
					texture2DCompare( shadowMap, cubeToUV( bd3D + offset.xyy, texelSize.y ), dp ) +
					texture2DCompare( shadowMap, cubeToUV( bd3D + offset.yyy, texelSize.y ), dp ) +
					texture2DCompare( shadowMap, cubeToUV( bd3D + offset.xyx, texelSize.y ), dp ) +
					texture2DCompare( shadowMap, cubeToUV( bd3D + offset.yyx, texelSize.y ), dp ) +
					texture2DCompare( shadowMap, cubeToUV( bd3D, texelSize.y ), dp ) +
					texture2DCompare( shadowMap, cubeToUV( bd3D + offset.xxy, texelSize.y ), dp ) +
					texture2DCompare( shadowMap, cubeToUV( bd3D + offset.yxy, texelSize.y ), dp ) +
					texture2DCompare( shadowMap, cubeToUV( bd3D + offset.xxx, texelSize.y ), dp ) +
					texture2DCompare( shadowMap, cubeToUV( bd3D + offset.yxx, texelSize.y ), dp )
				) * ( 1.0 / 9.0 );
			#else
				shadow = texture2DCompare( shadowMap, cubeToUV( bd3D, texelSize.y ), dp );
			#endif
		}
		return mix( 1.0, shadow, shadowIntensity );
	}
#endif`,Mp=`#if NUM_SPOT_LIGHT_COORDS > 0
	uniform mat4 spotLightMatrix[ NUM_SPOT_LIGHT_COORDS ];
	varying vec4 vSpotLightCoord[ NUM_SPOT_LIGHT_COORDS ];
#endif
#ifdef USE_SHADOWMAP
	#if NUM_DIR_LIGHT_SHADOWS > 0
		uniform mat4 directionalShadowMatrix[ NUM_DIR_LIGHT_SHADOWS ];
		varying vec4 vDirectionalShadowCoord[ NUM_DIR_LIGHT_SHADOWS ];
		struct DirectionalLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
		};
		uniform DirectionalLightShadow directionalLightShadows[ NUM_DIR_LIGHT_SHADOWS ];
	#endif
	#if NUM_SPOT_LIGHT_SHADOWS > 0
		struct SpotLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
		};
		uniform SpotLightShadow spotLightShadows[ NUM_SPOT_LIGHT_SHADOWS ];
	#endif
	#if NUM_POINT_LIGHT_SHADOWS > 0
		uniform mat4 pointShadowMatrix[ NUM_POINT_LIGHT_SHADOWS ];
		varying vec4 vPointShadowCoord[ NUM_POINT_LIGHT_SHADOWS ];
		struct PointLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
			float shadowCameraNear;
			float shadowCameraFar;
		};
		uniform PointLightShadow pointLightShadows[ NUM_POINT_LIGHT_SHADOWS ];
	#endif
#endif`,_p=`#if ( defined( USE_SHADOWMAP ) && ( NUM_DIR_LIGHT_SHADOWS > 0 || NUM_POINT_LIGHT_SHADOWS > 0 ) ) || ( NUM_SPOT_LIGHT_COORDS > 0 )
	vec3 shadowWorldNormal = inverseTransformDirection( transformedNormal, viewMatrix );
	vec4 shadowWorldPosition;
#endif
#if defined( USE_SHADOWMAP )
	#if NUM_DIR_LIGHT_SHADOWS > 0
		#pragma unroll_loop_start
		for ( int i = 0; i < NUM_DIR_LIGHT_SHADOWS; i ++ ) {
			shadowWorldPosition = worldPosition + vec4( shadowWorldNormal * directionalLightShadows[ i ].shadowNormalBias, 0 );
			vDirectionalShadowCoord[ i ] = directionalShadowMatrix[ i ] * shadowWorldPosition;
		}
		#pragma unroll_loop_end
	#endif
	#if NUM_POINT_LIGHT_SHADOWS > 0
		#pragma unroll_loop_start
		for ( int i = 0; i < NUM_POINT_LIGHT_SHADOWS; i ++ ) {
			shadowWorldPosition = worldPosition + vec4( shadowWorldNormal * pointLightShadows[ i ].shadowNormalBias, 0 );
			vPointShadowCoord[ i ] = pointShadowMatrix[ i ] * shadowWorldPosition;
		}
		#pragma unroll_loop_end
	#endif
#endif
#if NUM_SPOT_LIGHT_COORDS > 0
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_SPOT_LIGHT_COORDS; i ++ ) {
		shadowWorldPosition = worldPosition;
		#if ( defined( USE_SHADOWMAP ) && UNROLLED_LOOP_INDEX < NUM_SPOT_LIGHT_SHADOWS )
			shadowWorldPosition.xyz += shadowWorldNormal * spotLightShadows[ i ].shadowNormalBias;
		#endif
		vSpotLightCoord[ i ] = spotLightMatrix[ i ] * shadowWorldPosition;
	}
	#pragma unroll_loop_end
#endif`,Ep=`float getShadowMask() {
	float shadow = 1.0;
	#ifdef USE_SHADOWMAP
	#if NUM_DIR_LIGHT_SHADOWS > 0
	DirectionalLightShadow directionalLight;
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_DIR_LIGHT_SHADOWS; i ++ ) {
		directionalLight = directionalLightShadows[ i ];
		shadow *= receiveShadow ? getShadow( directionalShadowMap[ i ], directionalLight.shadowMapSize, directionalLight.shadowIntensity, directionalLight.shadowBias, directionalLight.shadowRadius, vDirectionalShadowCoord[ i ] ) : 1.0;
	}
	#pragma unroll_loop_end
	#endif
	#if NUM_SPOT_LIGHT_SHADOWS > 0
	SpotLightShadow spotLight;
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_SPOT_LIGHT_SHADOWS; i ++ ) {
		spotLight = spotLightShadows[ i ];
		shadow *= receiveShadow ? getShadow( spotShadowMap[ i ], spotLight.shadowMapSize, spotLight.shadowIntensity, spotLight.shadowBias, spotLight.shadowRadius, vSpotLightCoord[ i ] ) : 1.0;
	}
	#pragma unroll_loop_end
	#endif
	#if NUM_POINT_LIGHT_SHADOWS > 0
	PointLightShadow pointLight;
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_POINT_LIGHT_SHADOWS; i ++ ) {
		pointLight = pointLightShadows[ i ];
		shadow *= receiveShadow ? getPointShadow( pointShadowMap[ i ], pointLight.shadowMapSize, pointLight.shadowIntensity, pointLight.shadowBias, pointLight.shadowRadius, vPointShadowCoord[ i ], pointLight.shadowCameraNear, pointLight.shadowCameraFar ) : 1.0;
	}
	#pragma unroll_loop_end
	#endif
	#endif
	return shadow;
}`,Sp=`#ifdef USE_SKINNING
	mat4 boneMatX = getBoneMatrix( skinIndex.x );
	mat4 boneMatY = getBoneMatrix( skinIndex.y );
	mat4 boneMatZ = getBoneMatrix( skinIndex.z );
	mat4 boneMatW = getBoneMatrix( skinIndex.w );
#endif`,Ap=`#ifdef USE_SKINNING
	uniform mat4 bindMatrix;
	uniform mat4 bindMatrixInverse;
	uniform highp sampler2D boneTexture;
	mat4 getBoneMatrix( const in float i ) {
		int size = textureSize( boneTexture, 0 ).x;
		int j = int( i ) * 4;
		int x = j % size;
		int y = j / size;
		vec4 v1 = texelFetch( boneTexture, ivec2( x, y ), 0 );
		vec4 v2 = texelFetch( boneTexture, ivec2( x + 1, y ), 0 );
		vec4 v3 = texelFetch( boneTexture, ivec2( x + 2, y ), 0 );
		vec4 v4 = texelFetch( boneTexture, ivec2( x + 3, y ), 0 );
		return mat4( v1, v2, v3, v4 );
	}
#endif`,Tp=`#ifdef USE_SKINNING
	vec4 skinVertex = bindMatrix * vec4( transformed, 1.0 );
	vec4 skinned = vec4( 0.0 );
	skinned += boneMatX * skinVertex * skinWeight.x;
	skinned += boneMatY * skinVertex * skinWeight.y;
	skinned += boneMatZ * skinVertex * skinWeight.z;
	skinned += boneMatW * skinVertex * skinWeight.w;
	transformed = ( bindMatrixInverse * skinned ).xyz;
#endif`,kp=`#ifdef USE_SKINNING
	mat4 skinMatrix = mat4( 0.0 );
	skinMatrix += skinWeight.x * boneMatX;
	skinMatrix += skinWeight.y * boneMatY;
	skinMatrix += skinWeight.z * boneMatZ;
	skinMatrix += skinWeight.w * boneMatW;
	skinMatrix = bindMatrixInverse * skinMatrix * bindMatrix;
	objectNormal = vec4( skinMatrix * vec4( objectNormal, 0.0 ) ).xyz;
	#ifdef USE_TANGENT
		objectTangent = vec4( skinMatrix * vec4( objectTangent, 0.0 ) ).xyz;
	#endif
#endif`,Rp=`float specularStrength;
#ifdef USE_SPECULARMAP
	vec4 texelSpecular = texture2D( specularMap, vSpecularMapUv );
	specularStrength = texelSpecular.r;
#else
	specularStrength = 1.0;
#endif`,Cp=`#ifdef USE_SPECULARMAP
	uniform sampler2D specularMap;
#endif`,Ip=`#if defined( TONE_MAPPING )
	gl_FragColor.rgb = toneMapping( gl_FragColor.rgb );
#endif`,Pp=`#ifndef saturate
#define saturate( a ) clamp( a, 0.0, 1.0 )
#endif
uniform float toneMappingExposure;
vec3 LinearToneMapping( vec3 color ) {
	return saturate( toneMappingExposure * color );
}
vec3 ReinhardToneMapping( vec3 color ) {
	color *= toneMappingExposure;
	return saturate( color / ( vec3( 1.0 ) + color ) );
}
vec3 CineonToneMapping( vec3 color ) {
	color *= toneMappingExposure;
	color = max( vec3( 0.0 ), color - 0.004 );
	return pow( ( color * ( 6.2 * color + 0.5 ) ) / ( color * ( 6.2 * color + 1.7 ) + 0.06 ), vec3( 2.2 ) );
}
vec3 RRTAndODTFit( vec3 v ) {
	vec3 a = v * ( v + 0.0245786 ) - 0.000090537;
	vec3 b = v * ( 0.983729 * v + 0.4329510 ) + 0.238081;
	return a / b;
}
vec3 ACESFilmicToneMapping( vec3 color ) {
	const mat3 ACESInputMat = mat3(
		vec3( 0.59719, 0.07600, 0.02840 ),		vec3( 0.35458, 0.90834, 0.13383 ),
		vec3( 0.04823, 0.01566, 0.83777 )
	);
	const mat3 ACESOutputMat = mat3(
		vec3(  1.60475, -0.10208, -0.00327 ),		vec3( -0.53108,  1.10813, -0.07276 ),
		vec3( -0.07367, -0.00605,  1.07602 )
	);
	color *= toneMappingExposure / 0.6;
	color = ACESInputMat * color;
	color = RRTAndODTFit( color );
	color = ACESOutputMat * color;
	return saturate( color );
}
const mat3 LINEAR_REC2020_TO_LINEAR_SRGB = mat3(
	vec3( 1.6605, - 0.1246, - 0.0182 ),
	vec3( - 0.5876, 1.1329, - 0.1006 ),
	vec3( - 0.0728, - 0.0083, 1.1187 )
);
const mat3 LINEAR_SRGB_TO_LINEAR_REC2020 = mat3(
	vec3( 0.6274, 0.0691, 0.0164 ),
	vec3( 0.3293, 0.9195, 0.0880 ),
	vec3( 0.0433, 0.0113, 0.8956 )
);
vec3 agxDefaultContrastApprox( vec3 x ) {
	vec3 x2 = x * x;
	vec3 x4 = x2 * x2;
	return + 15.5 * x4 * x2
		- 40.14 * x4 * x
		+ 31.96 * x4
		- 6.868 * x2 * x
		+ 0.4298 * x2
		+ 0.1191 * x
		- 0.00232;
}
vec3 AgXToneMapping( vec3 color ) {
	const mat3 AgXInsetMatrix = mat3(
		vec3( 0.856627153315983, 0.137318972929847, 0.11189821299995 ),
		vec3( 0.0951212405381588, 0.761241990602591, 0.0767994186031903 ),
		vec3( 0.0482516061458583, 0.101439036467562, 0.811302368396859 )
	);
	const mat3 AgXOutsetMatrix = mat3(
		vec3( 1.1271005818144368, - 0.1413297634984383, - 0.14132976349843826 ),
		vec3( - 0.11060664309660323, 1.157823702216272, - 0.11060664309660294 ),
		vec3( - 0.016493938717834573, - 0.016493938717834257, 1.2519364065950405 )
	);
	const float AgxMinEv = - 12.47393;	const float AgxMaxEv = 4.026069;
	color *= toneMappingExposure;
	color = LINEAR_SRGB_TO_LINEAR_REC2020 * color;
	color = AgXInsetMatrix * color;
	color = max( color, 1e-10 );	color = log2( color );
	color = ( color - AgxMinEv ) / ( AgxMaxEv - AgxMinEv );
	color = clamp( color, 0.0, 1.0 );
	color = agxDefaultContrastApprox( color );
	color = AgXOutsetMatrix * color;
	color = pow( max( vec3( 0.0 ), color ), vec3( 2.2 ) );
	color = LINEAR_REC2020_TO_LINEAR_SRGB * color;
	color = clamp( color, 0.0, 1.0 );
	return color;
}
vec3 NeutralToneMapping( vec3 color ) {
	const float StartCompression = 0.8 - 0.04;
	const float Desaturation = 0.15;
	color *= toneMappingExposure;
	float x = min( color.r, min( color.g, color.b ) );
	float offset = x < 0.08 ? x - 6.25 * x * x : 0.04;
	color -= offset;
	float peak = max( color.r, max( color.g, color.b ) );
	if ( peak < StartCompression ) return color;
	float d = 1. - StartCompression;
	float newPeak = 1. - d * d / ( peak + d - StartCompression );
	color *= newPeak / peak;
	float g = 1. - 1. / ( Desaturation * ( peak - newPeak ) + 1. );
	return mix( color, vec3( newPeak ), g );
}
vec3 CustomToneMapping( vec3 color ) { return color; }`,Dp=`#ifdef USE_TRANSMISSION
	material.transmission = transmission;
	material.transmissionAlpha = 1.0;
	material.thickness = thickness;
	material.attenuationDistance = attenuationDistance;
	material.attenuationColor = attenuationColor;
	#ifdef USE_TRANSMISSIONMAP
		material.transmission *= texture2D( transmissionMap, vTransmissionMapUv ).r;
	#endif
	#ifdef USE_THICKNESSMAP
		material.thickness *= texture2D( thicknessMap, vThicknessMapUv ).g;
	#endif
	vec3 pos = vWorldPosition;
	vec3 v = normalize( cameraPosition - pos );
	vec3 n = inverseTransformDirection( normal, viewMatrix );
	vec4 transmitted = getIBLVolumeRefraction(
		n, v, material.roughness, material.diffuseColor, material.specularColor, material.specularF90,
		pos, modelMatrix, viewMatrix, projectionMatrix, material.dispersion, material.ior, material.thickness,
		material.attenuationColor, material.attenuationDistance );
	material.transmissionAlpha = mix( material.transmissionAlpha, transmitted.a, material.transmission );
	totalDiffuse = mix( totalDiffuse, transmitted.rgb, material.transmission );
#endif`,Np=`#ifdef USE_TRANSMISSION
	uniform float transmission;
	uniform float thickness;
	uniform float attenuationDistance;
	uniform vec3 attenuationColor;
	#ifdef USE_TRANSMISSIONMAP
		uniform sampler2D transmissionMap;
	#endif
	#ifdef USE_THICKNESSMAP
		uniform sampler2D thicknessMap;
	#endif
	uniform vec2 transmissionSamplerSize;
	uniform sampler2D transmissionSamplerMap;
	uniform mat4 modelMatrix;
	uniform mat4 projectionMatrix;
	varying vec3 vWorldPosition;
	float w0( float a ) {
		return ( 1.0 / 6.0 ) * ( a * ( a * ( - a + 3.0 ) - 3.0 ) + 1.0 );
	}
	float w1( float a ) {
		return ( 1.0 / 6.0 ) * ( a *  a * ( 3.0 * a - 6.0 ) + 4.0 );
	}
	float w2( float a ){
		return ( 1.0 / 6.0 ) * ( a * ( a * ( - 3.0 * a + 3.0 ) + 3.0 ) + 1.0 );
	}
	float w3( float a ) {
		return ( 1.0 / 6.0 ) * ( a * a * a );
	}
	float g0( float a ) {
		return w0( a ) + w1( a );
	}
	float g1( float a ) {
		return w2( a ) + w3( a );
	}
	float h0( float a ) {
		return - 1.0 + w1( a ) / ( w0( a ) + w1( a ) );
	}
	float h1( float a ) {
		return 1.0 + w3( a ) / ( w2( a ) + w3( a ) );
	}
	vec4 bicubic( sampler2D tex, vec2 uv, vec4 texelSize, float lod ) {
		uv = uv * texelSize.zw + 0.5;
		vec2 iuv = floor( uv );
		vec2 fuv = fract( uv );
		float g0x = g0( fuv.x );
		float g1x = g1( fuv.x );
		float h0x = h0( fuv.x );
		float h1x = h1( fuv.x );
		float h0y = h0( fuv.y );
		float h1y = h1( fuv.y );
		vec2 p0 = ( vec2( iuv.x + h0x, iuv.y + h0y ) - 0.5 ) * texelSize.xy;
		vec2 p1 = ( vec2( iuv.x + h1x, iuv.y + h0y ) - 0.5 ) * texelSize.xy;
		vec2 p2 = ( vec2( iuv.x + h0x, iuv.y + h1y ) - 0.5 ) * texelSize.xy;
		vec2 p3 = ( vec2( iuv.x + h1x, iuv.y + h1y ) - 0.5 ) * texelSize.xy;
		return g0( fuv.y ) * ( g0x * textureLod( tex, p0, lod ) + g1x * textureLod( tex, p1, lod ) ) +
			g1( fuv.y ) * ( g0x * textureLod( tex, p2, lod ) + g1x * textureLod( tex, p3, lod ) );
	}
	vec4 textureBicubic( sampler2D sampler, vec2 uv, float lod ) {
		vec2 fLodSize = vec2( textureSize( sampler, int( lod ) ) );
		vec2 cLodSize = vec2( textureSize( sampler, int( lod + 1.0 ) ) );
		vec2 fLodSizeInv = 1.0 / fLodSize;
		vec2 cLodSizeInv = 1.0 / cLodSize;
		vec4 fSample = bicubic( sampler, uv, vec4( fLodSizeInv, fLodSize ), floor( lod ) );
		vec4 cSample = bicubic( sampler, uv, vec4( cLodSizeInv, cLodSize ), ceil( lod ) );
		return mix( fSample, cSample, fract( lod ) );
	}
	vec3 getVolumeTransmissionRay( const in vec3 n, const in vec3 v, const in float thickness, const in float ior, const in mat4 modelMatrix ) {
		vec3 refractionVector = refract( - v, normalize( n ), 1.0 / ior );
		vec3 modelScale;
		modelScale.x = length( vec3( modelMatrix[ 0 ].xyz ) );
		modelScale.y = length( vec3( modelMatrix[ 1 ].xyz ) );
		modelScale.z = length( vec3( modelMatrix[ 2 ].xyz ) );
		return normalize( refractionVector ) * thickness * modelScale;
	}
	float applyIorToRoughness( const in float roughness, const in float ior ) {
		return roughness * clamp( ior * 2.0 - 2.0, 0.0, 1.0 );
	}
	vec4 getTransmissionSample( const in vec2 fragCoord, const in float roughness, const in float ior ) {
		float lod = log2( transmissionSamplerSize.x ) * applyIorToRoughness( roughness, ior );
		return textureBicubic( transmissionSamplerMap, fragCoord.xy, lod );
	}
	vec3 volumeAttenuation( const in float transmissionDistance, const in vec3 attenuationColor, const in float attenuationDistance ) {
		if ( isinf( attenuationDistance ) ) {
			return vec3( 1.0 );
		} else {
			vec3 attenuationCoefficient = -log( attenuationColor ) / attenuationDistance;
			vec3 transmittance = exp( - attenuationCoefficient * transmissionDistance );			return transmittance;
		}
	}
	vec4 getIBLVolumeRefraction( const in vec3 n, const in vec3 v, const in float roughness, const in vec3 diffuseColor,
		const in vec3 specularColor, const in float specularF90, const in vec3 position, const in mat4 modelMatrix,
		const in mat4 viewMatrix, const in mat4 projMatrix, const in float dispersion, const in float ior, const in float thickness,
		const in vec3 attenuationColor, const in float attenuationDistance ) {
		vec4 transmittedLight;
		vec3 transmittance;
		#ifdef USE_DISPERSION
			float halfSpread = ( ior - 1.0 ) * 0.025 * dispersion;
			vec3 iors = vec3( ior - halfSpread, ior, ior + halfSpread );
			for ( int i = 0; i < 3; i ++ ) {
				vec3 transmissionRay = getVolumeTransmissionRay( n, v, thickness, iors[ i ], modelMatrix );
				vec3 refractedRayExit = position + transmissionRay;
		
				vec4 ndcPos = projMatrix * viewMatrix * vec4( refractedRayExit, 1.0 );
				vec2 refractionCoords = ndcPos.xy / ndcPos.w;
				refractionCoords += 1.0;
				refractionCoords /= 2.0;
		
				vec4 transmissionSample = getTransmissionSample( refractionCoords, roughness, iors[ i ] );
				transmittedLight[ i ] = transmissionSample[ i ];
				transmittedLight.a += transmissionSample.a;
				transmittance[ i ] = diffuseColor[ i ] * volumeAttenuation( length( transmissionRay ), attenuationColor, attenuationDistance )[ i ];
			}
			transmittedLight.a /= 3.0;
		
		#else
		
			vec3 transmissionRay = getVolumeTransmissionRay( n, v, thickness, ior, modelMatrix );
			vec3 refractedRayExit = position + transmissionRay;
			vec4 ndcPos = projMatrix * viewMatrix * vec4( refractedRayExit, 1.0 );
			vec2 refractionCoords = ndcPos.xy / ndcPos.w;
			refractionCoords += 1.0;
			refractionCoords /= 2.0;
			transmittedLight = getTransmissionSample( refractionCoords, roughness, ior );
			transmittance = diffuseColor * volumeAttenuation( length( transmissionRay ), attenuationColor, attenuationDistance );
		
		#endif
		vec3 attenuatedColor = transmittance * transmittedLight.rgb;
		vec3 F = EnvironmentBRDF( n, v, specularColor, specularF90, roughness );
		float transmittanceFactor = ( transmittance.r + transmittance.g + transmittance.b ) / 3.0;
		return vec4( ( 1.0 - F ) * attenuatedColor, 1.0 - ( 1.0 - transmittedLight.a ) * transmittanceFactor );
	}
#endif`,Up=`#if defined( USE_UV ) || defined( USE_ANISOTROPY )
	varying vec2 vUv;
#endif
#ifdef USE_MAP
	varying vec2 vMapUv;
#endif
#ifdef USE_ALPHAMAP
	varying vec2 vAlphaMapUv;
#endif
#ifdef USE_LIGHTMAP
	varying vec2 vLightMapUv;
#endif
#ifdef USE_AOMAP
	varying vec2 vAoMapUv;
#endif
#ifdef USE_BUMPMAP
	varying vec2 vBumpMapUv;
#endif
#ifdef USE_NORMALMAP
	varying vec2 vNormalMapUv;
#endif
#ifdef USE_EMISSIVEMAP
	varying vec2 vEmissiveMapUv;
#endif
#ifdef USE_METALNESSMAP
	varying vec2 vMetalnessMapUv;
#endif
#ifdef USE_ROUGHNESSMAP
	varying vec2 vRoughnessMapUv;
#endif
#ifdef USE_ANISOTROPYMAP
	varying vec2 vAnisotropyMapUv;
#endif
#ifdef USE_CLEARCOATMAP
	varying vec2 vClearcoatMapUv;
#endif
#ifdef USE_CLEARCOAT_NORMALMAP
	varying vec2 vClearcoatNormalMapUv;
#endif
#ifdef USE_CLEARCOAT_ROUGHNESSMAP
	varying vec2 vClearcoatRoughnessMapUv;
#endif
#ifdef USE_IRIDESCENCEMAP
	varying vec2 vIridescenceMapUv;
#endif
#ifdef USE_IRIDESCENCE_THICKNESSMAP
	varying vec2 vIridescenceThicknessMapUv;
#endif
#ifdef USE_SHEEN_COLORMAP
	varying vec2 vSheenColorMapUv;
#endif
#ifdef USE_SHEEN_ROUGHNESSMAP
	varying vec2 vSheenRoughnessMapUv;
#endif
#ifdef USE_SPECULARMAP
	varying vec2 vSpecularMapUv;
#endif
#ifdef USE_SPECULAR_COLORMAP
	varying vec2 vSpecularColorMapUv;
#endif
#ifdef USE_SPECULAR_INTENSITYMAP
	varying vec2 vSpecularIntensityMapUv;
#endif
#ifdef USE_TRANSMISSIONMAP
	uniform mat3 transmissionMapTransform;
	varying vec2 vTransmissionMapUv;
#endif
#ifdef USE_THICKNESSMAP
	uniform mat3 thicknessMapTransform;
	varying vec2 vThicknessMapUv;
#endif`,Fp=`#if defined( USE_UV ) || defined( USE_ANISOTROPY )
	varying vec2 vUv;
#endif
#ifdef USE_MAP
	uniform mat3 mapTransform;
	varying vec2 vMapUv;
#endif
#ifdef USE_ALPHAMAP
	uniform mat3 alphaMapTransform;
	varying vec2 vAlphaMapUv;
#endif
#ifdef USE_LIGHTMAP
	uniform mat3 lightMapTransform;
	varying vec2 vLightMapUv;
#endif
#ifdef USE_AOMAP
	uniform mat3 aoMapTransform;
	varying vec2 vAoMapUv;
#endif
#ifdef USE_BUMPMAP
	uniform mat3 bumpMapTransform;
	varying vec2 vBumpMapUv;
#endif
#ifdef USE_NORMALMAP
	uniform mat3 normalMapTransform;
	varying vec2 vNormalMapUv;
#endif
#ifdef USE_DISPLACEMENTMAP
	uniform mat3 displacementMapTransform;
	varying vec2 vDisplacementMapUv;
#endif
#ifdef USE_EMISSIVEMAP
	uniform mat3 emissiveMapTransform;
	varying vec2 vEmissiveMapUv;
#endif
#ifdef USE_METALNESSMAP
	uniform mat3 metalnessMapTransform;
	varying vec2 vMetalnessMapUv;
#endif
#ifdef USE_ROUGHNESSMAP
	uniform mat3 roughnessMapTransform;
	varying vec2 vRoughnessMapUv;
#endif
#ifdef USE_ANISOTROPYMAP
	uniform mat3 anisotropyMapTransform;
	varying vec2 vAnisotropyMapUv;
#endif
#ifdef USE_CLEARCOATMAP
	uniform mat3 clearcoatMapTransform;
	varying vec2 vClearcoatMapUv;
#endif
#ifdef USE_CLEARCOAT_NORMALMAP
	uniform mat3 clearcoatNormalMapTransform;
	varying vec2 vClearcoatNormalMapUv;
#endif
#ifdef USE_CLEARCOAT_ROUGHNESSMAP
	uniform mat3 clearcoatRoughnessMapTransform;
	varying vec2 vClearcoatRoughnessMapUv;
#endif
#ifdef USE_SHEEN_COLORMAP
	uniform mat3 sheenColorMapTransform;
	varying vec2 vSheenColorMapUv;
#endif
#ifdef USE_SHEEN_ROUGHNESSMAP
	uniform mat3 sheenRoughnessMapTransform;
	varying vec2 vSheenRoughnessMapUv;
#endif
#ifdef USE_IRIDESCENCEMAP
	uniform mat3 iridescenceMapTransform;
	varying vec2 vIridescenceMapUv;
#endif
#ifdef USE_IRIDESCENCE_THICKNESSMAP
	uniform mat3 iridescenceThicknessMapTransform;
	varying vec2 vIridescenceThicknessMapUv;
#endif
#ifdef USE_SPECULARMAP
	uniform mat3 specularMapTransform;
	varying vec2 vSpecularMapUv;
#endif
#ifdef USE_SPECULAR_COLORMAP
	uniform mat3 specularColorMapTransform;
	varying vec2 vSpecularColorMapUv;
#endif
#ifdef USE_SPECULAR_INTENSITYMAP
	uniform mat3 specularIntensityMapTransform;
	varying vec2 vSpecularIntensityMapUv;
#endif
#ifdef USE_TRANSMISSIONMAP
	uniform mat3 transmissionMapTransform;
	varying vec2 vTransmissionMapUv;
#endif
#ifdef USE_THICKNESSMAP
	uniform mat3 thicknessMapTransform;
	varying vec2 vThicknessMapUv;
#endif`,Lp=`#if defined( USE_UV ) || defined( USE_ANISOTROPY )
	vUv = vec3( uv, 1 ).xy;
#endif
#ifdef USE_MAP
	vMapUv = ( mapTransform * vec3( MAP_UV, 1 ) ).xy;
#endif
#ifdef USE_ALPHAMAP
	vAlphaMapUv = ( alphaMapTransform * vec3( ALPHAMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_LIGHTMAP
	vLightMapUv = ( lightMapTransform * vec3( LIGHTMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_AOMAP
	vAoMapUv = ( aoMapTransform * vec3( AOMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_BUMPMAP
	vBumpMapUv = ( bumpMapTransform * vec3( BUMPMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_NORMALMAP
	vNormalMapUv = ( normalMapTransform * vec3( NORMALMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_DISPLACEMENTMAP
	vDisplacementMapUv = ( displacementMapTransform * vec3( DISPLACEMENTMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_EMISSIVEMAP
	vEmissiveMapUv = ( emissiveMapTransform * vec3( EMISSIVEMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_METALNESSMAP
	vMetalnessMapUv = ( metalnessMapTransform * vec3( METALNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_ROUGHNESSMAP
	vRoughnessMapUv = ( roughnessMapTransform * vec3( ROUGHNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_ANISOTROPYMAP
	vAnisotropyMapUv = ( anisotropyMapTransform * vec3( ANISOTROPYMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_CLEARCOATMAP
	vClearcoatMapUv = ( clearcoatMapTransform * vec3( CLEARCOATMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_CLEARCOAT_NORMALMAP
	vClearcoatNormalMapUv = ( clearcoatNormalMapTransform * vec3( CLEARCOAT_NORMALMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_CLEARCOAT_ROUGHNESSMAP
	vClearcoatRoughnessMapUv = ( clearcoatRoughnessMapTransform * vec3( CLEARCOAT_ROUGHNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_IRIDESCENCEMAP
	vIridescenceMapUv = ( iridescenceMapTransform * vec3( IRIDESCENCEMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_IRIDESCENCE_THICKNESSMAP
	vIridescenceThicknessMapUv = ( iridescenceThicknessMapTransform * vec3( IRIDESCENCE_THICKNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_SHEEN_COLORMAP
	vSheenColorMapUv = ( sheenColorMapTransform * vec3( SHEEN_COLORMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_SHEEN_ROUGHNESSMAP
	vSheenRoughnessMapUv = ( sheenRoughnessMapTransform * vec3( SHEEN_ROUGHNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_SPECULARMAP
	vSpecularMapUv = ( specularMapTransform * vec3( SPECULARMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_SPECULAR_COLORMAP
	vSpecularColorMapUv = ( specularColorMapTransform * vec3( SPECULAR_COLORMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_SPECULAR_INTENSITYMAP
	vSpecularIntensityMapUv = ( specularIntensityMapTransform * vec3( SPECULAR_INTENSITYMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_TRANSMISSIONMAP
	vTransmissionMapUv = ( transmissionMapTransform * vec3( TRANSMISSIONMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_THICKNESSMAP
	vThicknessMapUv = ( thicknessMapTransform * vec3( THICKNESSMAP_UV, 1 ) ).xy;
#endif`,jp=`#if defined( USE_ENVMAP ) || defined( DISTANCE ) || defined ( USE_SHADOWMAP ) || defined ( USE_TRANSMISSION ) || NUM_SPOT_LIGHT_COORDS > 0
	vec4 worldPosition = vec4( transformed, 1.0 );
	#ifdef USE_BATCHING
		worldPosition = batchingMatrix * worldPosition;
	#endif
	#ifdef USE_INSTANCING
		worldPosition = instanceMatrix * worldPosition;
	#endif
	worldPosition = modelMatrix * worldPosition;
#endif`;const Op=`varying vec2 vUv;
uniform mat3 uvTransform;
void main() {
	vUv = ( uvTransform * vec3( uv, 1 ) ).xy;
	gl_Position = vec4( position.xy, 1.0, 1.0 );
}`,zp=`uniform sampler2D t2D;
uniform float backgroundIntensity;
varying vec2 vUv;
void main() {
	vec4 texColor = texture2D( t2D, vUv );
	#ifdef DECODE_VIDEO_TEXTURE
		texColor = vec4( mix( pow( texColor.rgb * 0.9478672986 + vec3( 0.0521327014 ), vec3( 2.4 ) ), texColor.rgb * 0.0773993808, vec3( lessThanEqual( texColor.rgb, vec3( 0.04045 ) ) ) ), texColor.w );
	#endif
	texColor.rgb *= backgroundIntensity;
	gl_FragColor = texColor;
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
}`,Bp=`varying vec3 vWorldDirection;
#include <common>
void main() {
	vWorldDirection = transformDirection( position, modelMatrix );
	#include <begin_vertex>
	#include <project_vertex>
	gl_Position.z = gl_Position.w;
}`,Gp=`#ifdef ENVMAP_TYPE_CUBE
	uniform samplerCube envMap;
#elif defined( ENVMAP_TYPE_CUBE_UV )
	uniform sampler2D envMap;
#endif
uniform float flipEnvMap;
uniform float backgroundBlurriness;
uniform float backgroundIntensity;
uniform mat3 backgroundRotation;
varying vec3 vWorldDirection;
#include <cube_uv_reflection_fragment>
void main() {
	#ifdef ENVMAP_TYPE_CUBE
		vec4 texColor = textureCube( envMap, backgroundRotation * vec3( flipEnvMap * vWorldDirection.x, vWorldDirection.yz ) );
	#elif defined( ENVMAP_TYPE_CUBE_UV )
		vec4 texColor = textureCubeUV( envMap, backgroundRotation * vWorldDirection, backgroundBlurriness );
	#else
		vec4 texColor = vec4( 0.0, 0.0, 0.0, 1.0 );
	#endif
	texColor.rgb *= backgroundIntensity;
	gl_FragColor = texColor;
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
}`,Hp=`varying vec3 vWorldDirection;
#include <common>
void main() {
	vWorldDirection = transformDirection( position, modelMatrix );
	#include <begin_vertex>
	#include <project_vertex>
	gl_Position.z = gl_Position.w;
}`,Vp=`uniform samplerCube tCube;
uniform float tFlip;
uniform float opacity;
varying vec3 vWorldDirection;
void main() {
	vec4 texColor = textureCube( tCube, vec3( tFlip * vWorldDirection.x, vWorldDirection.yz ) );
	gl_FragColor = texColor;
	gl_FragColor.a *= opacity;
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
}`,Wp=`#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
varying vec2 vHighPrecisionZW;
void main() {
	#include <uv_vertex>
	#include <batching_vertex>
	#include <skinbase_vertex>
	#include <morphinstance_vertex>
	#ifdef USE_DISPLACEMENTMAP
		#include <beginnormal_vertex>
		#include <morphnormal_vertex>
		#include <skinnormal_vertex>
	#endif
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	vHighPrecisionZW = gl_Position.zw;
}`,qp=`#if DEPTH_PACKING == 3200
	uniform float opacity;
#endif
#include <common>
#include <packing>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
varying vec2 vHighPrecisionZW;
void main() {
	vec4 diffuseColor = vec4( 1.0 );
	#include <clipping_planes_fragment>
	#if DEPTH_PACKING == 3200
		diffuseColor.a = opacity;
	#endif
	#include <map_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <logdepthbuf_fragment>
	float fragCoordZ = 0.5 * vHighPrecisionZW[0] / vHighPrecisionZW[1] + 0.5;
	#if DEPTH_PACKING == 3200
		gl_FragColor = vec4( vec3( 1.0 - fragCoordZ ), opacity );
	#elif DEPTH_PACKING == 3201
		gl_FragColor = packDepthToRGBA( fragCoordZ );
	#elif DEPTH_PACKING == 3202
		gl_FragColor = vec4( packDepthToRGB( fragCoordZ ), 1.0 );
	#elif DEPTH_PACKING == 3203
		gl_FragColor = vec4( packDepthToRG( fragCoordZ ), 0.0, 1.0 );
	#endif
}`,Xp=`#define DISTANCE
varying vec3 vWorldPosition;
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <batching_vertex>
	#include <skinbase_vertex>
	#include <morphinstance_vertex>
	#ifdef USE_DISPLACEMENTMAP
		#include <beginnormal_vertex>
		#include <morphnormal_vertex>
		#include <skinnormal_vertex>
	#endif
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <worldpos_vertex>
	#include <clipping_planes_vertex>
	vWorldPosition = worldPosition.xyz;
}`,Kp=`#define DISTANCE
uniform vec3 referencePosition;
uniform float nearDistance;
uniform float farDistance;
varying vec3 vWorldPosition;
#include <common>
#include <packing>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <clipping_planes_pars_fragment>
void main () {
	vec4 diffuseColor = vec4( 1.0 );
	#include <clipping_planes_fragment>
	#include <map_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	float dist = length( vWorldPosition - referencePosition );
	dist = ( dist - nearDistance ) / ( farDistance - nearDistance );
	dist = saturate( dist );
	gl_FragColor = packDepthToRGBA( dist );
}`,Jp=`varying vec3 vWorldDirection;
#include <common>
void main() {
	vWorldDirection = transformDirection( position, modelMatrix );
	#include <begin_vertex>
	#include <project_vertex>
}`,Yp=`uniform sampler2D tEquirect;
varying vec3 vWorldDirection;
#include <common>
void main() {
	vec3 direction = normalize( vWorldDirection );
	vec2 sampleUV = equirectUv( direction );
	gl_FragColor = texture2D( tEquirect, sampleUV );
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
}`,Zp=`uniform float scale;
attribute float lineDistance;
varying float vLineDistance;
#include <common>
#include <uv_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <morphtarget_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	vLineDistance = scale * lineDistance;
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	#include <fog_vertex>
}`,Qp=`uniform vec3 diffuse;
uniform float opacity;
uniform float dashSize;
uniform float totalSize;
varying float vLineDistance;
#include <common>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <fog_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	if ( mod( vLineDistance, totalSize ) > dashSize ) {
		discard;
	}
	vec3 outgoingLight = vec3( 0.0 );
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	outgoingLight = diffuseColor.rgb;
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
}`,$p=`#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <envmap_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#if defined ( USE_ENVMAP ) || defined ( USE_SKINNING )
		#include <beginnormal_vertex>
		#include <morphnormal_vertex>
		#include <skinbase_vertex>
		#include <skinnormal_vertex>
		#include <defaultnormal_vertex>
	#endif
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	#include <worldpos_vertex>
	#include <envmap_vertex>
	#include <fog_vertex>
}`,eg=`uniform vec3 diffuse;
uniform float opacity;
#ifndef FLAT_SHADED
	varying vec3 vNormal;
#endif
#include <common>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <aomap_pars_fragment>
#include <lightmap_pars_fragment>
#include <envmap_common_pars_fragment>
#include <envmap_pars_fragment>
#include <fog_pars_fragment>
#include <specularmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <specularmap_fragment>
	ReflectedLight reflectedLight = ReflectedLight( vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ) );
	#ifdef USE_LIGHTMAP
		vec4 lightMapTexel = texture2D( lightMap, vLightMapUv );
		reflectedLight.indirectDiffuse += lightMapTexel.rgb * lightMapIntensity * RECIPROCAL_PI;
	#else
		reflectedLight.indirectDiffuse += vec3( 1.0 );
	#endif
	#include <aomap_fragment>
	reflectedLight.indirectDiffuse *= diffuseColor.rgb;
	vec3 outgoingLight = reflectedLight.indirectDiffuse;
	#include <envmap_fragment>
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,tg=`#define LAMBERT
varying vec3 vViewPosition;
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <envmap_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <shadowmap_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	vViewPosition = - mvPosition.xyz;
	#include <worldpos_vertex>
	#include <envmap_vertex>
	#include <shadowmap_vertex>
	#include <fog_vertex>
}`,ag=`#define LAMBERT
uniform vec3 diffuse;
uniform vec3 emissive;
uniform float opacity;
#include <common>
#include <packing>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <aomap_pars_fragment>
#include <lightmap_pars_fragment>
#include <emissivemap_pars_fragment>
#include <envmap_common_pars_fragment>
#include <envmap_pars_fragment>
#include <fog_pars_fragment>
#include <bsdfs>
#include <lights_pars_begin>
#include <normal_pars_fragment>
#include <lights_lambert_pars_fragment>
#include <shadowmap_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <specularmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	ReflectedLight reflectedLight = ReflectedLight( vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ) );
	vec3 totalEmissiveRadiance = emissive;
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <specularmap_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	#include <emissivemap_fragment>
	#include <lights_lambert_fragment>
	#include <lights_fragment_begin>
	#include <lights_fragment_maps>
	#include <lights_fragment_end>
	#include <aomap_fragment>
	vec3 outgoingLight = reflectedLight.directDiffuse + reflectedLight.indirectDiffuse + totalEmissiveRadiance;
	#include <envmap_fragment>
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,ng=`#define MATCAP
varying vec3 vViewPosition;
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <color_pars_vertex>
#include <displacementmap_pars_vertex>
#include <fog_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	#include <fog_vertex>
	vViewPosition = - mvPosition.xyz;
}`,ig=`#define MATCAP
uniform vec3 diffuse;
uniform float opacity;
uniform sampler2D matcap;
varying vec3 vViewPosition;
#include <common>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <fog_pars_fragment>
#include <normal_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	vec3 viewDir = normalize( vViewPosition );
	vec3 x = normalize( vec3( viewDir.z, 0.0, - viewDir.x ) );
	vec3 y = cross( viewDir, x );
	vec2 uv = vec2( dot( x, normal ), dot( y, normal ) ) * 0.495 + 0.5;
	#ifdef USE_MATCAP
		vec4 matcapColor = texture2D( matcap, uv );
	#else
		vec4 matcapColor = vec4( vec3( mix( 0.2, 0.8, uv.y ) ), 1.0 );
	#endif
	vec3 outgoingLight = diffuseColor.rgb * matcapColor.rgb;
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,rg=`#define NORMAL
#if defined( FLAT_SHADED ) || defined( USE_BUMPMAP ) || defined( USE_NORMALMAP_TANGENTSPACE )
	varying vec3 vViewPosition;
#endif
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphinstance_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
#if defined( FLAT_SHADED ) || defined( USE_BUMPMAP ) || defined( USE_NORMALMAP_TANGENTSPACE )
	vViewPosition = - mvPosition.xyz;
#endif
}`,sg=`#define NORMAL
uniform float opacity;
#if defined( FLAT_SHADED ) || defined( USE_BUMPMAP ) || defined( USE_NORMALMAP_TANGENTSPACE )
	varying vec3 vViewPosition;
#endif
#include <packing>
#include <uv_pars_fragment>
#include <normal_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( 0.0, 0.0, 0.0, opacity );
	#include <clipping_planes_fragment>
	#include <logdepthbuf_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	gl_FragColor = vec4( packNormalToRGB( normal ), diffuseColor.a );
	#ifdef OPAQUE
		gl_FragColor.a = 1.0;
	#endif
}`,og=`#define PHONG
varying vec3 vViewPosition;
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <envmap_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <shadowmap_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphinstance_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	vViewPosition = - mvPosition.xyz;
	#include <worldpos_vertex>
	#include <envmap_vertex>
	#include <shadowmap_vertex>
	#include <fog_vertex>
}`,cg=`#define PHONG
uniform vec3 diffuse;
uniform vec3 emissive;
uniform vec3 specular;
uniform float shininess;
uniform float opacity;
#include <common>
#include <packing>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <aomap_pars_fragment>
#include <lightmap_pars_fragment>
#include <emissivemap_pars_fragment>
#include <envmap_common_pars_fragment>
#include <envmap_pars_fragment>
#include <fog_pars_fragment>
#include <bsdfs>
#include <lights_pars_begin>
#include <normal_pars_fragment>
#include <lights_phong_pars_fragment>
#include <shadowmap_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <specularmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	ReflectedLight reflectedLight = ReflectedLight( vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ) );
	vec3 totalEmissiveRadiance = emissive;
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <specularmap_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	#include <emissivemap_fragment>
	#include <lights_phong_fragment>
	#include <lights_fragment_begin>
	#include <lights_fragment_maps>
	#include <lights_fragment_end>
	#include <aomap_fragment>
	vec3 outgoingLight = reflectedLight.directDiffuse + reflectedLight.indirectDiffuse + reflectedLight.directSpecular + reflectedLight.indirectSpecular + totalEmissiveRadiance;
	#include <envmap_fragment>
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,hg=`#define STANDARD
varying vec3 vViewPosition;
#ifdef USE_TRANSMISSION
	varying vec3 vWorldPosition;
#endif
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <shadowmap_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	vViewPosition = - mvPosition.xyz;
	#include <worldpos_vertex>
	#include <shadowmap_vertex>
	#include <fog_vertex>
#ifdef USE_TRANSMISSION
	vWorldPosition = worldPosition.xyz;
#endif
}`,lg=`#define STANDARD
#ifdef PHYSICAL
	#define IOR
	#define USE_SPECULAR
#endif
uniform vec3 diffuse;
uniform vec3 emissive;
uniform float roughness;
uniform float metalness;
uniform float opacity;
#ifdef IOR
	uniform float ior;
#endif
#ifdef USE_SPECULAR
	uniform float specularIntensity;
	uniform vec3 specularColor;
	#ifdef USE_SPECULAR_COLORMAP
		uniform sampler2D specularColorMap;
	#endif
	#ifdef USE_SPECULAR_INTENSITYMAP
		uniform sampler2D specularIntensityMap;
	#endif
#endif
#ifdef USE_CLEARCOAT
	uniform float clearcoat;
	uniform float clearcoatRoughness;
#endif
#ifdef USE_DISPERSION
	uniform float dispersion;
#endif
#ifdef USE_IRIDESCENCE
	uniform float iridescence;
	uniform float iridescenceIOR;
	uniform float iridescenceThicknessMinimum;
	uniform float iridescenceThicknessMaximum;
#endif
#ifdef USE_SHEEN
	uniform vec3 sheenColor;
	uniform float sheenRoughness;
	#ifdef USE_SHEEN_COLORMAP
		uniform sampler2D sheenColorMap;
	#endif
	#ifdef USE_SHEEN_ROUGHNESSMAP
		uniform sampler2D sheenRoughnessMap;
	#endif
#endif
#ifdef USE_ANISOTROPY
	uniform vec2 anisotropyVector;
	#ifdef USE_ANISOTROPYMAP
		uniform sampler2D anisotropyMap;
	#endif
#endif
varying vec3 vViewPosition;
#include <common>
#include <packing>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <aomap_pars_fragment>
#include <lightmap_pars_fragment>
#include <emissivemap_pars_fragment>
#include <iridescence_fragment>
#include <cube_uv_reflection_fragment>
#include <envmap_common_pars_fragment>
#include <envmap_physical_pars_fragment>
#include <fog_pars_fragment>
#include <lights_pars_begin>
#include <normal_pars_fragment>
#include <lights_physical_pars_fragment>
#include <transmission_pars_fragment>
#include <shadowmap_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <clearcoat_pars_fragment>
#include <iridescence_pars_fragment>
#include <roughnessmap_pars_fragment>
#include <metalnessmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	ReflectedLight reflectedLight = ReflectedLight( vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ) );
	vec3 totalEmissiveRadiance = emissive;
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <roughnessmap_fragment>
	#include <metalnessmap_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	#include <clearcoat_normal_fragment_begin>
	#include <clearcoat_normal_fragment_maps>
	#include <emissivemap_fragment>
	#include <lights_physical_fragment>
	#include <lights_fragment_begin>
	#include <lights_fragment_maps>
	#include <lights_fragment_end>
	#include <aomap_fragment>
	vec3 totalDiffuse = reflectedLight.directDiffuse + reflectedLight.indirectDiffuse;
	vec3 totalSpecular = reflectedLight.directSpecular + reflectedLight.indirectSpecular;
	#include <transmission_fragment>
	vec3 outgoingLight = totalDiffuse + totalSpecular + totalEmissiveRadiance;
	#ifdef USE_SHEEN
		float sheenEnergyComp = 1.0 - 0.157 * max3( material.sheenColor );
		outgoingLight = outgoingLight * sheenEnergyComp + sheenSpecularDirect + sheenSpecularIndirect;
	#endif
	#ifdef USE_CLEARCOAT
		float dotNVcc = saturate( dot( geometryClearcoatNormal, geometryViewDir ) );
		vec3 Fcc = F_Schlick( material.clearcoatF0, material.clearcoatF90, dotNVcc );
		outgoingLight = outgoingLight * ( 1.0 - material.clearcoat * Fcc ) + ( clearcoatSpecularDirect + clearcoatSpecularIndirect ) * material.clearcoat;
	#endif
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,dg=`#define TOON
varying vec3 vViewPosition;
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <shadowmap_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	vViewPosition = - mvPosition.xyz;
	#include <worldpos_vertex>
	#include <shadowmap_vertex>
	#include <fog_vertex>
}`,fg=`#define TOON
uniform vec3 diffuse;
uniform vec3 emissive;
uniform float opacity;
#include <common>
#include <packing>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <aomap_pars_fragment>
#include <lightmap_pars_fragment>
#include <emissivemap_pars_fragment>
#include <gradientmap_pars_fragment>
#include <fog_pars_fragment>
#include <bsdfs>
#include <lights_pars_begin>
#include <normal_pars_fragment>
#include <lights_toon_pars_fragment>
#include <shadowmap_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	ReflectedLight reflectedLight = ReflectedLight( vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ) );
	vec3 totalEmissiveRadiance = emissive;
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	#include <emissivemap_fragment>
	#include <lights_toon_fragment>
	#include <lights_fragment_begin>
	#include <lights_fragment_maps>
	#include <lights_fragment_end>
	#include <aomap_fragment>
	vec3 outgoingLight = reflectedLight.directDiffuse + reflectedLight.indirectDiffuse + totalEmissiveRadiance;
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,ug=`uniform float size;
uniform float scale;
#include <common>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <morphtarget_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
#ifdef USE_POINTS_UV
	varying vec2 vUv;
	uniform mat3 uvTransform;
#endif
void main() {
	#ifdef USE_POINTS_UV
		vUv = ( uvTransform * vec3( uv, 1 ) ).xy;
	#endif
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <project_vertex>
	gl_PointSize = size;
	#ifdef USE_SIZEATTENUATION
		bool isPerspective = isPerspectiveMatrix( projectionMatrix );
		if ( isPerspective ) gl_PointSize *= ( scale / - mvPosition.z );
	#endif
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	#include <worldpos_vertex>
	#include <fog_vertex>
}`,bg=`uniform vec3 diffuse;
uniform float opacity;
#include <common>
#include <color_pars_fragment>
#include <map_particle_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <fog_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	vec3 outgoingLight = vec3( 0.0 );
	#include <logdepthbuf_fragment>
	#include <map_particle_fragment>
	#include <color_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	outgoingLight = diffuseColor.rgb;
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
}`,mg=`#include <common>
#include <batching_pars_vertex>
#include <fog_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <shadowmap_pars_vertex>
void main() {
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphinstance_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <worldpos_vertex>
	#include <shadowmap_vertex>
	#include <fog_vertex>
}`,pg=`uniform vec3 color;
uniform float opacity;
#include <common>
#include <packing>
#include <fog_pars_fragment>
#include <bsdfs>
#include <lights_pars_begin>
#include <logdepthbuf_pars_fragment>
#include <shadowmap_pars_fragment>
#include <shadowmask_pars_fragment>
void main() {
	#include <logdepthbuf_fragment>
	gl_FragColor = vec4( color, opacity * ( 1.0 - getShadowMask() ) );
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
}`,gg=`uniform float rotation;
uniform vec2 center;
#include <common>
#include <uv_pars_vertex>
#include <fog_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	vec4 mvPosition = modelViewMatrix[ 3 ];
	vec2 scale = vec2( length( modelMatrix[ 0 ].xyz ), length( modelMatrix[ 1 ].xyz ) );
	#ifndef USE_SIZEATTENUATION
		bool isPerspective = isPerspectiveMatrix( projectionMatrix );
		if ( isPerspective ) scale *= - mvPosition.z;
	#endif
	vec2 alignedPosition = ( position.xy - ( center - vec2( 0.5 ) ) ) * scale;
	vec2 rotatedPosition;
	rotatedPosition.x = cos( rotation ) * alignedPosition.x - sin( rotation ) * alignedPosition.y;
	rotatedPosition.y = sin( rotation ) * alignedPosition.x + cos( rotation ) * alignedPosition.y;
	mvPosition.xy += rotatedPosition;
	gl_Position = projectionMatrix * mvPosition;
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	#include <fog_vertex>
}`,vg=`uniform vec3 diffuse;
uniform float opacity;
#include <common>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <fog_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	vec3 outgoingLight = vec3( 0.0 );
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	outgoingLight = diffuseColor.rgb;
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
}`,Le={alphahash_fragment:zb,alphahash_pars_fragment:Bb,alphamap_fragment:Gb,alphamap_pars_fragment:Hb,alphatest_fragment:Vb,alphatest_pars_fragment:Wb,aomap_fragment:qb,aomap_pars_fragment:Xb,batching_pars_vertex:Kb,batching_vertex:Jb,begin_vertex:Yb,beginnormal_vertex:Zb,bsdfs:Qb,iridescence_fragment:$b,bumpmap_pars_fragment:em,clipping_planes_fragment:tm,clipping_planes_pars_fragment:am,clipping_planes_pars_vertex:nm,clipping_planes_vertex:im,color_fragment:rm,color_pars_fragment:sm,color_pars_vertex:om,color_vertex:cm,common:hm,cube_uv_reflection_fragment:lm,defaultnormal_vertex:dm,displacementmap_pars_vertex:fm,displacementmap_vertex:um,emissivemap_fragment:bm,emissivemap_pars_fragment:mm,colorspace_fragment:pm,colorspace_pars_fragment:gm,envmap_fragment:vm,envmap_common_pars_fragment:ym,envmap_pars_fragment:xm,envmap_pars_vertex:wm,envmap_physical_pars_fragment:Pm,envmap_vertex:Mm,fog_vertex:_m,fog_pars_vertex:Em,fog_fragment:Sm,fog_pars_fragment:Am,gradientmap_pars_fragment:Tm,lightmap_pars_fragment:km,lights_lambert_fragment:Rm,lights_lambert_pars_fragment:Cm,lights_pars_begin:Im,lights_toon_fragment:Dm,lights_toon_pars_fragment:Nm,lights_phong_fragment:Um,lights_phong_pars_fragment:Fm,lights_physical_fragment:Lm,lights_physical_pars_fragment:jm,lights_fragment_begin:Om,lights_fragment_maps:zm,lights_fragment_end:Bm,logdepthbuf_fragment:Gm,logdepthbuf_pars_fragment:Hm,logdepthbuf_pars_vertex:Vm,logdepthbuf_vertex:Wm,map_fragment:qm,map_pars_fragment:Xm,map_particle_fragment:Km,map_particle_pars_fragment:Jm,metalnessmap_fragment:Ym,metalnessmap_pars_fragment:Zm,morphinstance_vertex:Qm,morphcolor_vertex:$m,morphnormal_vertex:ep,morphtarget_pars_vertex:tp,morphtarget_vertex:ap,normal_fragment_begin:np,normal_fragment_maps:ip,normal_pars_fragment:rp,normal_pars_vertex:sp,normal_vertex:op,normalmap_pars_fragment:cp,clearcoat_normal_fragment_begin:hp,clearcoat_normal_fragment_maps:lp,clearcoat_pars_fragment:dp,iridescence_pars_fragment:fp,opaque_fragment:up,packing:bp,premultiplied_alpha_fragment:mp,project_vertex:pp,dithering_fragment:gp,dithering_pars_fragment:vp,roughnessmap_fragment:yp,roughnessmap_pars_fragment:xp,shadowmap_pars_fragment:wp,shadowmap_pars_vertex:Mp,shadowmap_vertex:_p,shadowmask_pars_fragment:Ep,skinbase_vertex:Sp,skinning_pars_vertex:Ap,skinning_vertex:Tp,skinnormal_vertex:kp,specularmap_fragment:Rp,specularmap_pars_fragment:Cp,tonemapping_fragment:Ip,tonemapping_pars_fragment:Pp,transmission_fragment:Dp,transmission_pars_fragment:Np,uv_pars_fragment:Up,uv_pars_vertex:Fp,uv_vertex:Lp,worldpos_vertex:jp,background_vert:Op,background_frag:zp,backgroundCube_vert:Bp,backgroundCube_frag:Gp,cube_vert:Hp,cube_frag:Vp,depth_vert:Wp,depth_frag:qp,distanceRGBA_vert:Xp,distanceRGBA_frag:Kp,equirect_vert:Jp,equirect_frag:Yp,linedashed_vert:Zp,linedashed_frag:Qp,meshbasic_vert:$p,meshbasic_frag:eg,meshlambert_vert:tg,meshlambert_frag:ag,meshmatcap_vert:ng,meshmatcap_frag:ig,meshnormal_vert:rg,meshnormal_frag:sg,meshphong_vert:og,meshphong_frag:cg,meshphysical_vert:hg,meshphysical_frag:lg,meshtoon_vert:dg,meshtoon_frag:fg,points_vert:ug,points_frag:bg,shadow_vert:mg,shadow_frag:pg,sprite_vert:gg,sprite_frag:vg},oe={common:{diffuse:{value:new Ve(16777215)},opacity:{value:1},map:{value:null},mapTransform:{value:new Pe},alphaMap:{value:null},alphaMapTransform:{value:new Pe},alphaTest:{value:0}},specularmap:{specularMap:{value:null},specularMapTransform:{value:new Pe}},envmap:{envMap:{value:null},envMapRotation:{value:new Pe},flipEnvMap:{value:-1},reflectivity:{value:1},ior:{value:1.5},refractionRatio:{value:.98}},aomap:{aoMap:{value:null},aoMapIntensity:{value:1},aoMapTransform:{value:new Pe}},lightmap:{lightMap:{value:null},lightMapIntensity:{value:1},lightMapTransform:{value:new Pe}},bumpmap:{bumpMap:{value:null},bumpMapTransform:{value:new Pe},bumpScale:{value:1}},normalmap:{normalMap:{value:null},normalMapTransform:{value:new Pe},normalScale:{value:new De(1,1)}},displacementmap:{displacementMap:{value:null},displacementMapTransform:{value:new Pe},displacementScale:{value:1},displacementBias:{value:0}},emissivemap:{emissiveMap:{value:null},emissiveMapTransform:{value:new Pe}},metalnessmap:{metalnessMap:{value:null},metalnessMapTransform:{value:new Pe}},roughnessmap:{roughnessMap:{value:null},roughnessMapTransform:{value:new Pe}},gradientmap:{gradientMap:{value:null}},fog:{fogDensity:{value:25e-5},fogNear:{value:1},fogFar:{value:2e3},fogColor:{value:new Ve(16777215)}},lights:{ambientLightColor:{value:[]},lightProbe:{value:[]},directionalLights:{value:[],properties:{direction:{},color:{}}},directionalLightShadows:{value:[],properties:{shadowIntensity:1,shadowBias:{},shadowNormalBias:{},shadowRadius:{},shadowMapSize:{}}},directionalShadowMap:{value:[]},directionalShadowMatrix:{value:[]},spotLights:{value:[],properties:{color:{},position:{},direction:{},distance:{},coneCos:{},penumbraCos:{},decay:{}}},spotLightShadows:{value:[],properties:{shadowIntensity:1,shadowBias:{},shadowNormalBias:{},shadowRadius:{},shadowMapSize:{}}},spotLightMap:{value:[]},spotShadowMap:{value:[]},spotLightMatrix:{value:[]},pointLights:{value:[],properties:{color:{},position:{},decay:{},distance:{}}},pointLightShadows:{value:[],properties:{shadowIntensity:1,shadowBias:{},shadowNormalBias:{},shadowRadius:{},shadowMapSize:{},shadowCameraNear:{},shadowCameraFar:{}}},pointShadowMap:{value:[]},pointShadowMatrix:{value:[]},hemisphereLights:{value:[],properties:{direction:{},skyColor:{},groundColor:{}}},rectAreaLights:{value:[],properties:{color:{},position:{},width:{},height:{}}},ltc_1:{value:null},ltc_2:{value:null}},points:{diffuse:{value:new Ve(16777215)},opacity:{value:1},size:{value:1},scale:{value:1},map:{value:null},alphaMap:{value:null},alphaMapTransform:{value:new Pe},alphaTest:{value:0},uvTransform:{value:new Pe}},sprite:{diffuse:{value:new Ve(16777215)},opacity:{value:1},center:{value:new De(.5,.5)},rotation:{value:0},map:{value:null},mapTransform:{value:new Pe},alphaMap:{value:null},alphaMapTransform:{value:new Pe},alphaTest:{value:0}}},sa={basic:{uniforms:Tt([oe.common,oe.specularmap,oe.envmap,oe.aomap,oe.lightmap,oe.fog]),vertexShader:Le.meshbasic_vert,fragmentShader:Le.meshbasic_frag},lambert:{uniforms:Tt([oe.common,oe.specularmap,oe.envmap,oe.aomap,oe.lightmap,oe.emissivemap,oe.bumpmap,oe.normalmap,oe.displacementmap,oe.fog,oe.lights,{emissive:{value:new Ve(0)}}]),vertexShader:Le.meshlambert_vert,fragmentShader:Le.meshlambert_frag},phong:{uniforms:Tt([oe.common,oe.specularmap,oe.envmap,oe.aomap,oe.lightmap,oe.emissivemap,oe.bumpmap,oe.normalmap,oe.displacementmap,oe.fog,oe.lights,{emissive:{value:new Ve(0)},specular:{value:new Ve(1118481)},shininess:{value:30}}]),vertexShader:Le.meshphong_vert,fragmentShader:Le.meshphong_frag},standard:{uniforms:Tt([oe.common,oe.envmap,oe.aomap,oe.lightmap,oe.emissivemap,oe.bumpmap,oe.normalmap,oe.displacementmap,oe.roughnessmap,oe.metalnessmap,oe.fog,oe.lights,{emissive:{value:new Ve(0)},roughness:{value:1},metalness:{value:0},envMapIntensity:{value:1}}]),vertexShader:Le.meshphysical_vert,fragmentShader:Le.meshphysical_frag},toon:{uniforms:Tt([oe.common,oe.aomap,oe.lightmap,oe.emissivemap,oe.bumpmap,oe.normalmap,oe.displacementmap,oe.gradientmap,oe.fog,oe.lights,{emissive:{value:new Ve(0)}}]),vertexShader:Le.meshtoon_vert,fragmentShader:Le.meshtoon_frag},matcap:{uniforms:Tt([oe.common,oe.bumpmap,oe.normalmap,oe.displacementmap,oe.fog,{matcap:{value:null}}]),vertexShader:Le.meshmatcap_vert,fragmentShader:Le.meshmatcap_frag},points:{uniforms:Tt([oe.points,oe.fog]),vertexShader:Le.points_vert,fragmentShader:Le.points_frag},dashed:{uniforms:Tt([oe.common,oe.fog,{scale:{value:1},dashSize:{value:1},totalSize:{value:2}}]),vertexShader:Le.linedashed_vert,fragmentShader:Le.linedashed_frag},depth:{uniforms:Tt([oe.common,oe.displacementmap]),vertexShader:Le.depth_vert,fragmentShader:Le.depth_frag},normal:{uniforms:Tt([oe.common,oe.bumpmap,oe.normalmap,oe.displacementmap,{opacity:{value:1}}]),vertexShader:Le.meshnormal_vert,fragmentShader:Le.meshnormal_frag},sprite:{uniforms:Tt([oe.sprite,oe.fog]),vertexShader:Le.sprite_vert,fragmentShader:Le.sprite_frag},background:{uniforms:{uvTransform:{value:new Pe},t2D:{value:null},backgroundIntensity:{value:1}},vertexShader:Le.background_vert,fragmentShader:Le.background_frag},backgroundCube:{uniforms:{envMap:{value:null},flipEnvMap:{value:-1},backgroundBlurriness:{value:0},backgroundIntensity:{value:1},backgroundRotation:{value:new Pe}},vertexShader:Le.backgroundCube_vert,fragmentShader:Le.backgroundCube_frag},cube:{uniforms:{tCube:{value:null},tFlip:{value:-1},opacity:{value:1}},vertexShader:Le.cube_vert,fragmentShader:Le.cube_frag},equirect:{uniforms:{tEquirect:{value:null}},vertexShader:Le.equirect_vert,fragmentShader:Le.equirect_frag},distanceRGBA:{uniforms:Tt([oe.common,oe.displacementmap,{referencePosition:{value:new O},nearDistance:{value:1},farDistance:{value:1e3}}]),vertexShader:Le.distanceRGBA_vert,fragmentShader:Le.distanceRGBA_frag},shadow:{uniforms:Tt([oe.lights,oe.fog,{color:{value:new Ve(0)},opacity:{value:1}}]),vertexShader:Le.shadow_vert,fragmentShader:Le.shadow_frag}};sa.physical={uniforms:Tt([sa.standard.uniforms,{clearcoat:{value:0},clearcoatMap:{value:null},clearcoatMapTransform:{value:new Pe},clearcoatNormalMap:{value:null},clearcoatNormalMapTransform:{value:new Pe},clearcoatNormalScale:{value:new De(1,1)},clearcoatRoughness:{value:0},clearcoatRoughnessMap:{value:null},clearcoatRoughnessMapTransform:{value:new Pe},dispersion:{value:0},iridescence:{value:0},iridescenceMap:{value:null},iridescenceMapTransform:{value:new Pe},iridescenceIOR:{value:1.3},iridescenceThicknessMinimum:{value:100},iridescenceThicknessMaximum:{value:400},iridescenceThicknessMap:{value:null},iridescenceThicknessMapTransform:{value:new Pe},sheen:{value:0},sheenColor:{value:new Ve(0)},sheenColorMap:{value:null},sheenColorMapTransform:{value:new Pe},sheenRoughness:{value:1},sheenRoughnessMap:{value:null},sheenRoughnessMapTransform:{value:new Pe},transmission:{value:0},transmissionMap:{value:null},transmissionMapTransform:{value:new Pe},transmissionSamplerSize:{value:new De},transmissionSamplerMap:{value:null},thickness:{value:0},thicknessMap:{value:null},thicknessMapTransform:{value:new Pe},attenuationDistance:{value:0},attenuationColor:{value:new Ve(0)},specularColor:{value:new Ve(1,1,1)},specularColorMap:{value:null},specularColorMapTransform:{value:new Pe},specularIntensity:{value:1},specularIntensityMap:{value:null},specularIntensityMapTransform:{value:new Pe},anisotropyVector:{value:new De},anisotropyMap:{value:null},anisotropyMapTransform:{value:new Pe}}]),vertexShader:Le.meshphysical_vert,fragmentShader:Le.meshphysical_frag};const Ki={r:0,b:0,g:0},Za=new Aa,yg=new ze;function xg(n,e,t,a,i,r,s){const o=new Ve(0);let c=r===!0?0:1,l,h,d=null,f=0,b=null;function p(y){let x=y.isScene===!0?y.background:null;return x&&x.isTexture&&(x=(y.backgroundBlurriness>0?t:e).get(x)),x}function g(y){let x=!1;const v=p(y);v===null?u(o,c):v&&v.isColor&&(u(v,1),x=!0);const E=n.xr.getEnvironmentBlendMode();E==="additive"?a.buffers.color.setClear(0,0,0,1,s):E==="alpha-blend"&&a.buffers.color.setClear(0,0,0,0,s),(n.autoClear||x)&&(a.buffers.depth.setTest(!0),a.buffers.depth.setMask(!0),a.buffers.color.setMask(!0),n.clear(n.autoClearColor,n.autoClearDepth,n.autoClearStencil))}function m(y,x){const v=p(x);v&&(v.isCubeTexture||v.mapping===kr)?(h===void 0&&(h=new Nt(new Ti(1,1,1),new Jt({name:"BackgroundCubeMaterial",uniforms:zn(sa.backgroundCube.uniforms),vertexShader:sa.backgroundCube.vertexShader,fragmentShader:sa.backgroundCube.fragmentShader,side:Ut,depthTest:!1,depthWrite:!1,fog:!1})),h.geometry.deleteAttribute("normal"),h.geometry.deleteAttribute("uv"),h.onBeforeRender=function(E,_,A){this.matrixWorld.copyPosition(A.matrixWorld)},Object.defineProperty(h.material,"envMap",{get:function(){return this.uniforms.envMap.value}}),i.update(h)),Za.copy(x.backgroundRotation),Za.x*=-1,Za.y*=-1,Za.z*=-1,v.isCubeTexture&&v.isRenderTargetTexture===!1&&(Za.y*=-1,Za.z*=-1),h.material.uniforms.envMap.value=v,h.material.uniforms.flipEnvMap.value=v.isCubeTexture&&v.isRenderTargetTexture===!1?-1:1,h.material.uniforms.backgroundBlurriness.value=x.backgroundBlurriness,h.material.uniforms.backgroundIntensity.value=x.backgroundIntensity,h.material.uniforms.backgroundRotation.value.setFromMatrix4(yg.makeRotationFromEuler(Za)),h.material.toneMapped=qe.getTransfer(v.colorSpace)!==et,(d!==v||f!==v.version||b!==n.toneMapping)&&(h.material.needsUpdate=!0,d=v,f=v.version,b=n.toneMapping),h.layers.enableAll(),y.unshift(h,h.geometry,h.material,0,0,null)):v&&v.isTexture&&(l===void 0&&(l=new Nt(new Bn(2,2),new Jt({name:"BackgroundMaterial",uniforms:zn(sa.background.uniforms),vertexShader:sa.background.vertexShader,fragmentShader:sa.background.fragmentShader,side:Ma,depthTest:!1,depthWrite:!1,fog:!1})),l.geometry.deleteAttribute("normal"),Object.defineProperty(l.material,"map",{get:function(){return this.uniforms.t2D.value}}),i.update(l)),l.material.uniforms.t2D.value=v,l.material.uniforms.backgroundIntensity.value=x.backgroundIntensity,l.material.toneMapped=qe.getTransfer(v.colorSpace)!==et,v.matrixAutoUpdate===!0&&v.updateMatrix(),l.material.uniforms.uvTransform.value.copy(v.matrix),(d!==v||f!==v.version||b!==n.toneMapping)&&(l.material.needsUpdate=!0,d=v,f=v.version,b=n.toneMapping),l.layers.enableAll(),y.unshift(l,l.geometry,l.material,0,0,null))}function u(y,x){y.getRGB(Ki,ad(n)),a.buffers.color.setClear(Ki.r,Ki.g,Ki.b,x,s)}return{getClearColor:function(){return o},setClearColor:function(y,x=1){o.set(y),c=x,u(o,c)},getClearAlpha:function(){return c},setClearAlpha:function(y){c=y,u(o,c)},render:g,addToRenderList:m}}function wg(n,e){const t=n.getParameter(n.MAX_VERTEX_ATTRIBS),a={},i=f(null);let r=i,s=!1;function o(M,R,U,P,D){let V=!1;const B=d(P,U,R);r!==B&&(r=B,l(r.object)),V=b(M,P,U,D),V&&p(M,P,U,D),D!==null&&e.update(D,n.ELEMENT_ARRAY_BUFFER),(V||s)&&(s=!1,v(M,R,U,P),D!==null&&n.bindBuffer(n.ELEMENT_ARRAY_BUFFER,e.get(D).buffer))}function c(){return n.createVertexArray()}function l(M){return n.bindVertexArray(M)}function h(M){return n.deleteVertexArray(M)}function d(M,R,U){const P=U.wireframe===!0;let D=a[M.id];D===void 0&&(D={},a[M.id]=D);let V=D[R.id];V===void 0&&(V={},D[R.id]=V);let B=V[P];return B===void 0&&(B=f(c()),V[P]=B),B}function f(M){const R=[],U=[],P=[];for(let D=0;D<t;D++)R[D]=0,U[D]=0,P[D]=0;return{geometry:null,program:null,wireframe:!1,newAttributes:R,enabledAttributes:U,attributeDivisors:P,object:M,attributes:{},index:null}}function b(M,R,U,P){const D=r.attributes,V=R.attributes;let B=0;const G=U.getAttributes();for(const z in G)if(G[z].location>=0){const te=D[z];let ie=V[z];if(ie===void 0&&(z==="instanceMatrix"&&M.instanceMatrix&&(ie=M.instanceMatrix),z==="instanceColor"&&M.instanceColor&&(ie=M.instanceColor)),te===void 0||te.attribute!==ie||ie&&te.data!==ie.data)return!0;B++}return r.attributesNum!==B||r.index!==P}function p(M,R,U,P){const D={},V=R.attributes;let B=0;const G=U.getAttributes();for(const z in G)if(G[z].location>=0){let te=V[z];te===void 0&&(z==="instanceMatrix"&&M.instanceMatrix&&(te=M.instanceMatrix),z==="instanceColor"&&M.instanceColor&&(te=M.instanceColor));const ie={};ie.attribute=te,te&&te.data&&(ie.data=te.data),D[z]=ie,B++}r.attributes=D,r.attributesNum=B,r.index=P}function g(){const M=r.newAttributes;for(let R=0,U=M.length;R<U;R++)M[R]=0}function m(M){u(M,0)}function u(M,R){const U=r.newAttributes,P=r.enabledAttributes,D=r.attributeDivisors;U[M]=1,P[M]===0&&(n.enableVertexAttribArray(M),P[M]=1),D[M]!==R&&(n.vertexAttribDivisor(M,R),D[M]=R)}function y(){const M=r.newAttributes,R=r.enabledAttributes;for(let U=0,P=R.length;U<P;U++)R[U]!==M[U]&&(n.disableVertexAttribArray(U),R[U]=0)}function x(M,R,U,P,D,V,B){B===!0?n.vertexAttribIPointer(M,R,U,D,V):n.vertexAttribPointer(M,R,U,P,D,V)}function v(M,R,U,P){g();const D=P.attributes,V=U.getAttributes(),B=R.defaultAttributeValues;for(const G in V){const z=V[G];if(z.location>=0){let Y=D[G];if(Y===void 0&&(G==="instanceMatrix"&&M.instanceMatrix&&(Y=M.instanceMatrix),G==="instanceColor"&&M.instanceColor&&(Y=M.instanceColor)),Y!==void 0){const te=Y.normalized,ie=Y.itemSize,pe=e.get(Y);if(pe===void 0)continue;const Te=pe.buffer,W=pe.type,J=pe.bytesPerElement,se=W===n.INT||W===n.UNSIGNED_INT||Y.gpuType===Do;if(Y.isInterleavedBufferAttribute){const re=Y.data,ge=re.stride,Ae=Y.offset;if(re.isInstancedInterleavedBuffer){for(let Re=0;Re<z.locationSize;Re++)u(z.location+Re,re.meshPerAttribute);M.isInstancedMesh!==!0&&P._maxInstanceCount===void 0&&(P._maxInstanceCount=re.meshPerAttribute*re.count)}else for(let Re=0;Re<z.locationSize;Re++)m(z.location+Re);n.bindBuffer(n.ARRAY_BUFFER,Te);for(let Re=0;Re<z.locationSize;Re++)x(z.location+Re,ie/z.locationSize,W,te,ge*J,(Ae+ie/z.locationSize*Re)*J,se)}else{if(Y.isInstancedBufferAttribute){for(let re=0;re<z.locationSize;re++)u(z.location+re,Y.meshPerAttribute);M.isInstancedMesh!==!0&&P._maxInstanceCount===void 0&&(P._maxInstanceCount=Y.meshPerAttribute*Y.count)}else for(let re=0;re<z.locationSize;re++)m(z.location+re);n.bindBuffer(n.ARRAY_BUFFER,Te);for(let re=0;re<z.locationSize;re++)x(z.location+re,ie/z.locationSize,W,te,ie*J,ie/z.locationSize*re*J,se)}}else if(B!==void 0){const te=B[G];if(te!==void 0)switch(te.length){case 2:n.vertexAttrib2fv(z.location,te);break;case 3:n.vertexAttrib3fv(z.location,te);break;case 4:n.vertexAttrib4fv(z.location,te);break;default:n.vertexAttrib1fv(z.location,te)}}}}y()}function E(){k();for(const M in a){const R=a[M];for(const U in R){const P=R[U];for(const D in P)h(P[D].object),delete P[D];delete R[U]}delete a[M]}}function _(M){if(a[M.id]===void 0)return;const R=a[M.id];for(const U in R){const P=R[U];for(const D in P)h(P[D].object),delete P[D];delete R[U]}delete a[M.id]}function A(M){for(const R in a){const U=a[R];if(U[M.id]===void 0)continue;const P=U[M.id];for(const D in P)h(P[D].object),delete P[D];delete U[M.id]}}function k(){w(),s=!0,r!==i&&(r=i,l(r.object))}function w(){i.geometry=null,i.program=null,i.wireframe=!1}return{setup:o,reset:k,resetDefaultState:w,dispose:E,releaseStatesOfGeometry:_,releaseStatesOfProgram:A,initAttributes:g,enableAttribute:m,disableUnusedAttributes:y}}function Mg(n,e,t){let a;function i(l){a=l}function r(l,h){n.drawArrays(a,l,h),t.update(h,a,1)}function s(l,h,d){d!==0&&(n.drawArraysInstanced(a,l,h,d),t.update(h,a,d))}function o(l,h,d){if(d===0)return;e.get("WEBGL_multi_draw").multiDrawArraysWEBGL(a,l,0,h,0,d);let b=0;for(let p=0;p<d;p++)b+=h[p];t.update(b,a,1)}function c(l,h,d,f){if(d===0)return;const b=e.get("WEBGL_multi_draw");if(b===null)for(let p=0;p<l.length;p++)s(l[p],h[p],f[p]);else{b.multiDrawArraysInstancedWEBGL(a,l,0,h,0,f,0,d);let p=0;for(let g=0;g<d;g++)p+=h[g]*f[g];t.update(p,a,1)}}this.setMode=i,this.render=r,this.renderInstances=s,this.renderMultiDraw=o,this.renderMultiDrawInstances=c}function _g(n,e,t,a){let i;function r(){if(i!==void 0)return i;if(e.has("EXT_texture_filter_anisotropic")===!0){const A=e.get("EXT_texture_filter_anisotropic");i=n.getParameter(A.MAX_TEXTURE_MAX_ANISOTROPY_EXT)}else i=0;return i}function s(A){return!(A!==Rt&&a.convert(A)!==n.getParameter(n.IMPLEMENTATION_COLOR_READ_FORMAT))}function o(A){const k=A===Si&&(e.has("EXT_color_buffer_half_float")||e.has("EXT_color_buffer_float"));return!(A!==_a&&a.convert(A)!==n.getParameter(n.IMPLEMENTATION_COLOR_READ_TYPE)&&A!==zt&&!k)}function c(A){if(A==="highp"){if(n.getShaderPrecisionFormat(n.VERTEX_SHADER,n.HIGH_FLOAT).precision>0&&n.getShaderPrecisionFormat(n.FRAGMENT_SHADER,n.HIGH_FLOAT).precision>0)return"highp";A="mediump"}return A==="mediump"&&n.getShaderPrecisionFormat(n.VERTEX_SHADER,n.MEDIUM_FLOAT).precision>0&&n.getShaderPrecisionFormat(n.FRAGMENT_SHADER,n.MEDIUM_FLOAT).precision>0?"mediump":"lowp"}let l=t.precision!==void 0?t.precision:"highp";const h=c(l);h!==l&&(console.warn("THREE.WebGLRenderer:",l,"not supported, using",h,"instead."),l=h);const d=t.logarithmicDepthBuffer===!0,f=t.reverseDepthBuffer===!0&&e.has("EXT_clip_control"),b=n.getParameter(n.MAX_TEXTURE_IMAGE_UNITS),p=n.getParameter(n.MAX_VERTEX_TEXTURE_IMAGE_UNITS),g=n.getParameter(n.MAX_TEXTURE_SIZE),m=n.getParameter(n.MAX_CUBE_MAP_TEXTURE_SIZE),u=n.getParameter(n.MAX_VERTEX_ATTRIBS),y=n.getParameter(n.MAX_VERTEX_UNIFORM_VECTORS),x=n.getParameter(n.MAX_VARYING_VECTORS),v=n.getParameter(n.MAX_FRAGMENT_UNIFORM_VECTORS),E=p>0,_=n.getParameter(n.MAX_SAMPLES);return{isWebGL2:!0,getMaxAnisotropy:r,getMaxPrecision:c,textureFormatReadable:s,textureTypeReadable:o,precision:l,logarithmicDepthBuffer:d,reverseDepthBuffer:f,maxTextures:b,maxVertexTextures:p,maxTextureSize:g,maxCubemapSize:m,maxAttributes:u,maxVertexUniforms:y,maxVaryings:x,maxFragmentUniforms:v,vertexTextures:E,maxSamples:_}}function Eg(n){const e=this;let t=null,a=0,i=!1,r=!1;const s=new ja,o=new Pe,c={value:null,needsUpdate:!1};this.uniform=c,this.numPlanes=0,this.numIntersection=0,this.init=function(d,f){const b=d.length!==0||f||a!==0||i;return i=f,a=d.length,b},this.beginShadows=function(){r=!0,h(null)},this.endShadows=function(){r=!1},this.setGlobalState=function(d,f){t=h(d,f,0)},this.setState=function(d,f,b){const p=d.clippingPlanes,g=d.clipIntersection,m=d.clipShadows,u=n.get(d);if(!i||p===null||p.length===0||r&&!m)r?h(null):l();else{const y=r?0:a,x=y*4;let v=u.clippingState||null;c.value=v,v=h(p,f,x,b);for(let E=0;E!==x;++E)v[E]=t[E];u.clippingState=v,this.numIntersection=g?this.numPlanes:0,this.numPlanes+=y}};function l(){c.value!==t&&(c.value=t,c.needsUpdate=a>0),e.numPlanes=a,e.numIntersection=0}function h(d,f,b,p){const g=d!==null?d.length:0;let m=null;if(g!==0){if(m=c.value,p!==!0||m===null){const u=b+g*4,y=f.matrixWorldInverse;o.getNormalMatrix(y),(m===null||m.length<u)&&(m=new Float32Array(u));for(let x=0,v=b;x!==g;++x,v+=4)s.copy(d[x]).applyMatrix4(y,o),s.normal.toArray(m,v),m[v+3]=s.constant}c.value=m,c.needsUpdate=!0}return e.numPlanes=g,e.numIntersection=0,m}}function Sg(n){let e=new WeakMap;function t(s,o){return o===Bs?s.mapping=Fn:o===Gs&&(s.mapping=Ln),s}function a(s){if(s&&s.isTexture){const o=s.mapping;if(o===Bs||o===Gs)if(e.has(s)){const c=e.get(s).texture;return t(c,s.mapping)}else{const c=s.image;if(c&&c.height>0){const l=new Fb(c.height);return l.fromEquirectangularTexture(n,s),e.set(s,l),s.addEventListener("dispose",i),t(l.texture,s.mapping)}else return null}}return s}function i(s){const o=s.target;o.removeEventListener("dispose",i);const c=e.get(o);c!==void 0&&(e.delete(o),c.dispose())}function r(){e=new WeakMap}return{get:a,dispose:r}}class Bo extends nd{constructor(e=-1,t=1,a=1,i=-1,r=.1,s=2e3){super(),this.isOrthographicCamera=!0,this.type="OrthographicCamera",this.zoom=1,this.view=null,this.left=e,this.right=t,this.top=a,this.bottom=i,this.near=r,this.far=s,this.updateProjectionMatrix()}copy(e,t){return super.copy(e,t),this.left=e.left,this.right=e.right,this.top=e.top,this.bottom=e.bottom,this.near=e.near,this.far=e.far,this.zoom=e.zoom,this.view=e.view===null?null:Object.assign({},e.view),this}setViewOffset(e,t,a,i,r,s){this.view===null&&(this.view={enabled:!0,fullWidth:1,fullHeight:1,offsetX:0,offsetY:0,width:1,height:1}),this.view.enabled=!0,this.view.fullWidth=e,this.view.fullHeight=t,this.view.offsetX=a,this.view.offsetY=i,this.view.width=r,this.view.height=s,this.updateProjectionMatrix()}clearViewOffset(){this.view!==null&&(this.view.enabled=!1),this.updateProjectionMatrix()}updateProjectionMatrix(){const e=(this.right-this.left)/(2*this.zoom),t=(this.top-this.bottom)/(2*this.zoom),a=(this.right+this.left)/2,i=(this.top+this.bottom)/2;let r=a-e,s=a+e,o=i+t,c=i-t;if(this.view!==null&&this.view.enabled){const l=(this.right-this.left)/this.view.fullWidth/this.zoom,h=(this.top-this.bottom)/this.view.fullHeight/this.zoom;r+=l*this.view.offsetX,s=r+l*this.view.width,o-=h*this.view.offsetY,c=o-h*this.view.height}this.projectionMatrix.makeOrthographic(r,s,o,c,this.near,this.far,this.coordinateSystem),this.projectionMatrixInverse.copy(this.projectionMatrix).invert()}toJSON(e){const t=super.toJSON(e);return t.object.zoom=this.zoom,t.object.left=this.left,t.object.right=this.right,t.object.top=this.top,t.object.bottom=this.bottom,t.object.near=this.near,t.object.far=this.far,this.view!==null&&(t.object.view=Object.assign({},this.view)),t}}const Rn=4,Kc=[.125,.215,.35,.446,.526,.582],tn=20,rs=new Bo,Jc=new Ve;let ss=null,os=0,cs=0,hs=!1;const $a=(1+Math.sqrt(5))/2,An=1/$a,Yc=[new O(-$a,An,0),new O($a,An,0),new O(-An,0,$a),new O(An,0,$a),new O(0,$a,-An),new O(0,$a,An),new O(-1,1,-1),new O(1,1,-1),new O(-1,1,1),new O(1,1,1)];class Zc{constructor(e){this._renderer=e,this._pingPongRenderTarget=null,this._lodMax=0,this._cubeSize=0,this._lodPlanes=[],this._sizeLods=[],this._sigmas=[],this._blurMaterial=null,this._cubemapMaterial=null,this._equirectMaterial=null,this._compileMaterial(this._blurMaterial)}fromScene(e,t=0,a=.1,i=100){ss=this._renderer.getRenderTarget(),os=this._renderer.getActiveCubeFace(),cs=this._renderer.getActiveMipmapLevel(),hs=this._renderer.xr.enabled,this._renderer.xr.enabled=!1,this._setSize(256);const r=this._allocateTargets();return r.depthBuffer=!0,this._sceneToCubeUV(e,a,i,r),t>0&&this._blur(r,0,0,t),this._applyPMREM(r),this._cleanup(r),r}fromEquirectangular(e,t=null){return this._fromTexture(e,t)}fromCubemap(e,t=null){return this._fromTexture(e,t)}compileCubemapShader(){this._cubemapMaterial===null&&(this._cubemapMaterial=eh(),this._compileMaterial(this._cubemapMaterial))}compileEquirectangularShader(){this._equirectMaterial===null&&(this._equirectMaterial=$c(),this._compileMaterial(this._equirectMaterial))}dispose(){this._dispose(),this._cubemapMaterial!==null&&this._cubemapMaterial.dispose(),this._equirectMaterial!==null&&this._equirectMaterial.dispose()}_setSize(e){this._lodMax=Math.floor(Math.log2(e)),this._cubeSize=Math.pow(2,this._lodMax)}_dispose(){this._blurMaterial!==null&&this._blurMaterial.dispose(),this._pingPongRenderTarget!==null&&this._pingPongRenderTarget.dispose();for(let e=0;e<this._lodPlanes.length;e++)this._lodPlanes[e].dispose()}_cleanup(e){this._renderer.setRenderTarget(ss,os,cs),this._renderer.xr.enabled=hs,e.scissorTest=!1,Ji(e,0,0,e.width,e.height)}_fromTexture(e,t){e.mapping===Fn||e.mapping===Ln?this._setSize(e.image.length===0?16:e.image[0].width||e.image[0].image.width):this._setSize(e.image.width/4),ss=this._renderer.getRenderTarget(),os=this._renderer.getActiveCubeFace(),cs=this._renderer.getActiveMipmapLevel(),hs=this._renderer.xr.enabled,this._renderer.xr.enabled=!1;const a=t||this._allocateTargets();return this._textureToCubeUV(e,a),this._applyPMREM(a),this._cleanup(a),a}_allocateTargets(){const e=3*Math.max(this._cubeSize,112),t=4*this._cubeSize,a={magFilter:na,minFilter:na,generateMipmaps:!1,type:Si,format:Rt,colorSpace:Hn,depthBuffer:!1},i=Qc(e,t,a);if(this._pingPongRenderTarget===null||this._pingPongRenderTarget.width!==e||this._pingPongRenderTarget.height!==t){this._pingPongRenderTarget!==null&&this._dispose(),this._pingPongRenderTarget=Qc(e,t,a);const{_lodMax:r}=this;({sizeLods:this._sizeLods,lodPlanes:this._lodPlanes,sigmas:this._sigmas}=Ag(r)),this._blurMaterial=Tg(r,e,t)}return i}_compileMaterial(e){const t=new Nt(this._lodPlanes[0],e);this._renderer.compile(t,rs)}_sceneToCubeUV(e,t,a,i){const o=new Pt(90,1,t,a),c=[1,-1,1,1,1,1],l=[1,1,1,-1,-1,-1],h=this._renderer,d=h.autoClear,f=h.toneMapping;h.getClearColor(Jc),h.toneMapping=Ha,h.autoClear=!1;const b=new ed({name:"PMREM.Background",side:Ut,depthWrite:!1,depthTest:!1}),p=new Nt(new Ti,b);let g=!1;const m=e.background;m?m.isColor&&(b.color.copy(m),e.background=null,g=!0):(b.color.copy(Jc),g=!0);for(let u=0;u<6;u++){const y=u%3;y===0?(o.up.set(0,c[u],0),o.lookAt(l[u],0,0)):y===1?(o.up.set(0,0,c[u]),o.lookAt(0,l[u],0)):(o.up.set(0,c[u],0),o.lookAt(0,0,l[u]));const x=this._cubeSize;Ji(i,y*x,u>2?x:0,x,x),h.setRenderTarget(i),g&&h.render(p,o),h.render(e,o)}p.geometry.dispose(),p.material.dispose(),h.toneMapping=f,h.autoClear=d,e.background=m}_textureToCubeUV(e,t){const a=this._renderer,i=e.mapping===Fn||e.mapping===Ln;i?(this._cubemapMaterial===null&&(this._cubemapMaterial=eh()),this._cubemapMaterial.uniforms.flipEnvMap.value=e.isRenderTargetTexture===!1?-1:1):this._equirectMaterial===null&&(this._equirectMaterial=$c());const r=i?this._cubemapMaterial:this._equirectMaterial,s=new Nt(this._lodPlanes[0],r),o=r.uniforms;o.envMap.value=e;const c=this._cubeSize;Ji(t,0,0,3*c,2*c),a.setRenderTarget(t),a.render(s,rs)}_applyPMREM(e){const t=this._renderer,a=t.autoClear;t.autoClear=!1;const i=this._lodPlanes.length;for(let r=1;r<i;r++){const s=Math.sqrt(this._sigmas[r]*this._sigmas[r]-this._sigmas[r-1]*this._sigmas[r-1]),o=Yc[(i-r-1)%Yc.length];this._blur(e,r-1,r,s,o)}t.autoClear=a}_blur(e,t,a,i,r){const s=this._pingPongRenderTarget;this._halfBlur(e,s,t,a,i,"latitudinal",r),this._halfBlur(s,e,a,a,i,"longitudinal",r)}_halfBlur(e,t,a,i,r,s,o){const c=this._renderer,l=this._blurMaterial;s!=="latitudinal"&&s!=="longitudinal"&&console.error("blur direction must be either latitudinal or longitudinal!");const h=3,d=new Nt(this._lodPlanes[i],l),f=l.uniforms,b=this._sizeLods[a]-1,p=isFinite(r)?Math.PI/(2*b):2*Math.PI/(2*tn-1),g=r/p,m=isFinite(r)?1+Math.floor(h*g):tn;m>tn&&console.warn(`sigmaRadians, ${r}, is too large and will clip, as it requested ${m} samples when the maximum is set to ${tn}`);const u=[];let y=0;for(let A=0;A<tn;++A){const k=A/g,w=Math.exp(-k*k/2);u.push(w),A===0?y+=w:A<m&&(y+=2*w)}for(let A=0;A<u.length;A++)u[A]=u[A]/y;f.envMap.value=e.texture,f.samples.value=m,f.weights.value=u,f.latitudinal.value=s==="latitudinal",o&&(f.poleAxis.value=o);const{_lodMax:x}=this;f.dTheta.value=p,f.mipInt.value=x-a;const v=this._sizeLods[i],E=3*v*(i>x-Rn?i-x+Rn:0),_=4*(this._cubeSize-v);Ji(t,E,_,3*v,2*v),c.setRenderTarget(t),c.render(d,rs)}}function Ag(n){const e=[],t=[],a=[];let i=n;const r=n-Rn+1+Kc.length;for(let s=0;s<r;s++){const o=Math.pow(2,i);t.push(o);let c=1/o;s>n-Rn?c=Kc[s-n+Rn-1]:s===0&&(c=0),a.push(c);const l=1/(o-2),h=-l,d=1+l,f=[h,h,d,h,d,d,h,h,d,d,h,d],b=6,p=6,g=3,m=2,u=1,y=new Float32Array(g*p*b),x=new Float32Array(m*p*b),v=new Float32Array(u*p*b);for(let _=0;_<b;_++){const A=_%3*2/3-1,k=_>2?0:-1,w=[A,k,0,A+2/3,k,0,A+2/3,k+1,0,A,k,0,A+2/3,k+1,0,A,k+1,0];y.set(w,g*p*_),x.set(f,m*p*_);const M=[_,_,_,_,_,_];v.set(M,u*p*_)}const E=new pt;E.setAttribute("position",new Be(y,g)),E.setAttribute("uv",new Be(x,m)),E.setAttribute("faceIndex",new Be(v,u)),e.push(E),i>Rn&&i--}return{lodPlanes:e,sizeLods:t,sigmas:a}}function Qc(n,e,t){const a=new Sa(n,e,t);return a.texture.mapping=kr,a.texture.name="PMREM.cubeUv",a.scissorTest=!0,a}function Ji(n,e,t,a,i){n.viewport.set(e,t,a,i),n.scissor.set(e,t,a,i)}function Tg(n,e,t){const a=new Float32Array(tn),i=new O(0,1,0);return new Jt({name:"SphericalGaussianBlur",defines:{n:tn,CUBEUV_TEXEL_WIDTH:1/e,CUBEUV_TEXEL_HEIGHT:1/t,CUBEUV_MAX_MIP:`${n}.0`},uniforms:{envMap:{value:null},samples:{value:1},weights:{value:a},latitudinal:{value:!1},dTheta:{value:0},mipInt:{value:0},poleAxis:{value:i}},vertexShader:Go(),fragmentShader:`

			precision mediump float;
			precision mediump int;

			varying vec3 vOutputDirection;

			uniform sampler2D envMap;
			uniform int samples;
			uniform float weights[ n ];
			uniform bool latitudinal;
			uniform float dTheta;
			uniform float mipInt;
			uniform vec3 poleAxis;

			#define ENVMAP_TYPE_CUBE_UV
			#include <cube_uv_reflection_fragment>

			vec3 getSample( float theta, vec3 axis ) {

				float cosTheta = cos( theta );
				// Rodrigues' axis-angle rotation
				vec3 sampleDirection = vOutputDirection * cosTheta
					+ cross( axis, vOutputDirection ) * sin( theta )
					+ axis * dot( axis, vOutputDirection ) * ( 1.0 - cosTheta );

				return bilinearCubeUV( envMap, sampleDirection, mipInt );

			}

			void main() {

				vec3 axis = latitudinal ? poleAxis : cross( poleAxis, vOutputDirection );

				if ( all( equal( axis, vec3( 0.0 ) ) ) ) {

					axis = vec3( vOutputDirection.z, 0.0, - vOutputDirection.x );

				}

				axis = normalize( axis );

				gl_FragColor = vec4( 0.0, 0.0, 0.0, 1.0 );
				gl_FragColor.rgb += weights[ 0 ] * getSample( 0.0, axis );

				for ( int i = 1; i < n; i++ ) {

					if ( i >= samples ) {

						break;

					}

					float theta = dTheta * float( i );
					gl_FragColor.rgb += weights[ i ] * getSample( -1.0 * theta, axis );
					gl_FragColor.rgb += weights[ i ] * getSample( theta, axis );

				}

			}
		`,blending:Ga,depthTest:!1,depthWrite:!1})}function $c(){return new Jt({name:"EquirectangularToCubeUV",uniforms:{envMap:{value:null}},vertexShader:Go(),fragmentShader:`

			precision mediump float;
			precision mediump int;

			varying vec3 vOutputDirection;

			uniform sampler2D envMap;

			#include <common>

			void main() {

				vec3 outputDirection = normalize( vOutputDirection );
				vec2 uv = equirectUv( outputDirection );

				gl_FragColor = vec4( texture2D ( envMap, uv ).rgb, 1.0 );

			}
		`,blending:Ga,depthTest:!1,depthWrite:!1})}function eh(){return new Jt({name:"CubemapToCubeUV",uniforms:{envMap:{value:null},flipEnvMap:{value:-1}},vertexShader:Go(),fragmentShader:`

			precision mediump float;
			precision mediump int;

			uniform float flipEnvMap;

			varying vec3 vOutputDirection;

			uniform samplerCube envMap;

			void main() {

				gl_FragColor = textureCube( envMap, vec3( flipEnvMap * vOutputDirection.x, vOutputDirection.yz ) );

			}
		`,blending:Ga,depthTest:!1,depthWrite:!1})}function Go(){return`

		precision mediump float;
		precision mediump int;

		attribute float faceIndex;

		varying vec3 vOutputDirection;

		// RH coordinate system; PMREM face-indexing convention
		vec3 getDirection( vec2 uv, float face ) {

			uv = 2.0 * uv - 1.0;

			vec3 direction = vec3( uv, 1.0 );

			if ( face == 0.0 ) {

				direction = direction.zyx; // ( 1, v, u ) pos x

			} else if ( face == 1.0 ) {

				direction = direction.xzy;
				direction.xz *= -1.0; // ( -u, 1, -v ) pos y

			} else if ( face == 2.0 ) {

				direction.x *= -1.0; // ( -u, v, 1 ) pos z

			} else if ( face == 3.0 ) {

				direction = direction.zyx;
				direction.xz *= -1.0; // ( -1, v, -u ) neg x

			} else if ( face == 4.0 ) {

				direction = direction.xzy;
				direction.xy *= -1.0; // ( -u, -1, v ) neg y

			} else if ( face == 5.0 ) {

				direction.z *= -1.0; // ( u, v, -1 ) neg z

			}

			return direction;

		}

		void main() {

			vOutputDirection = getDirection( uv, faceIndex );
			gl_Position = vec4( position, 1.0 );

		}
	`}function kg(n){let e=new WeakMap,t=null;function a(o){if(o&&o.isTexture){const c=o.mapping,l=c===Bs||c===Gs,h=c===Fn||c===Ln;if(l||h){let d=e.get(o);const f=d!==void 0?d.texture.pmremVersion:0;if(o.isRenderTargetTexture&&o.pmremVersion!==f)return t===null&&(t=new Zc(n)),d=l?t.fromEquirectangular(o,d):t.fromCubemap(o,d),d.texture.pmremVersion=o.pmremVersion,e.set(o,d),d.texture;if(d!==void 0)return d.texture;{const b=o.image;return l&&b&&b.height>0||h&&b&&i(b)?(t===null&&(t=new Zc(n)),d=l?t.fromEquirectangular(o):t.fromCubemap(o),d.texture.pmremVersion=o.pmremVersion,e.set(o,d),o.addEventListener("dispose",r),d.texture):null}}}return o}function i(o){let c=0;const l=6;for(let h=0;h<l;h++)o[h]!==void 0&&c++;return c===l}function r(o){const c=o.target;c.removeEventListener("dispose",r);const l=e.get(c);l!==void 0&&(e.delete(c),l.dispose())}function s(){e=new WeakMap,t!==null&&(t.dispose(),t=null)}return{get:a,dispose:s}}function Rg(n){const e={};function t(a){if(e[a]!==void 0)return e[a];let i;switch(a){case"WEBGL_depth_texture":i=n.getExtension("WEBGL_depth_texture")||n.getExtension("MOZ_WEBGL_depth_texture")||n.getExtension("WEBKIT_WEBGL_depth_texture");break;case"EXT_texture_filter_anisotropic":i=n.getExtension("EXT_texture_filter_anisotropic")||n.getExtension("MOZ_EXT_texture_filter_anisotropic")||n.getExtension("WEBKIT_EXT_texture_filter_anisotropic");break;case"WEBGL_compressed_texture_s3tc":i=n.getExtension("WEBGL_compressed_texture_s3tc")||n.getExtension("MOZ_WEBGL_compressed_texture_s3tc")||n.getExtension("WEBKIT_WEBGL_compressed_texture_s3tc");break;case"WEBGL_compressed_texture_pvrtc":i=n.getExtension("WEBGL_compressed_texture_pvrtc")||n.getExtension("WEBKIT_WEBGL_compressed_texture_pvrtc");break;default:i=n.getExtension(a)}return e[a]=i,i}return{has:function(a){return t(a)!==null},init:function(){t("EXT_color_buffer_float"),t("WEBGL_clip_cull_distance"),t("OES_texture_float_linear"),t("EXT_color_buffer_half_float"),t("WEBGL_multisampled_render_to_texture"),t("WEBGL_render_shared_exponent")},get:function(a){const i=t(a);return i===null&&hi("THREE.WebGLRenderer: "+a+" extension not supported."),i}}}function Cg(n,e,t,a){const i={},r=new WeakMap;function s(d){const f=d.target;f.index!==null&&e.remove(f.index);for(const p in f.attributes)e.remove(f.attributes[p]);for(const p in f.morphAttributes){const g=f.morphAttributes[p];for(let m=0,u=g.length;m<u;m++)e.remove(g[m])}f.removeEventListener("dispose",s),delete i[f.id];const b=r.get(f);b&&(e.remove(b),r.delete(f)),a.releaseStatesOfGeometry(f),f.isInstancedBufferGeometry===!0&&delete f._maxInstanceCount,t.memory.geometries--}function o(d,f){return i[f.id]===!0||(f.addEventListener("dispose",s),i[f.id]=!0,t.memory.geometries++),f}function c(d){const f=d.attributes;for(const p in f)e.update(f[p],n.ARRAY_BUFFER);const b=d.morphAttributes;for(const p in b){const g=b[p];for(let m=0,u=g.length;m<u;m++)e.update(g[m],n.ARRAY_BUFFER)}}function l(d){const f=[],b=d.index,p=d.attributes.position;let g=0;if(b!==null){const y=b.array;g=b.version;for(let x=0,v=y.length;x<v;x+=3){const E=y[x+0],_=y[x+1],A=y[x+2];f.push(E,_,_,A,A,E)}}else if(p!==void 0){const y=p.array;g=p.version;for(let x=0,v=y.length/3-1;x<v;x+=3){const E=x+0,_=x+1,A=x+2;f.push(E,_,_,A,A,E)}}else return;const m=new(Jl(f)?td:zo)(f,1);m.version=g;const u=r.get(d);u&&e.remove(u),r.set(d,m)}function h(d){const f=r.get(d);if(f){const b=d.index;b!==null&&f.version<b.version&&l(d)}else l(d);return r.get(d)}return{get:o,update:c,getWireframeAttribute:h}}function Ig(n,e,t){let a;function i(f){a=f}let r,s;function o(f){r=f.type,s=f.bytesPerElement}function c(f,b){n.drawElements(a,b,r,f*s),t.update(b,a,1)}function l(f,b,p){p!==0&&(n.drawElementsInstanced(a,b,r,f*s,p),t.update(b,a,p))}function h(f,b,p){if(p===0)return;e.get("WEBGL_multi_draw").multiDrawElementsWEBGL(a,b,0,r,f,0,p);let m=0;for(let u=0;u<p;u++)m+=b[u];t.update(m,a,1)}function d(f,b,p,g){if(p===0)return;const m=e.get("WEBGL_multi_draw");if(m===null)for(let u=0;u<f.length;u++)l(f[u]/s,b[u],g[u]);else{m.multiDrawElementsInstancedWEBGL(a,b,0,r,f,0,g,0,p);let u=0;for(let y=0;y<p;y++)u+=b[y]*g[y];t.update(u,a,1)}}this.setMode=i,this.setIndex=o,this.render=c,this.renderInstances=l,this.renderMultiDraw=h,this.renderMultiDrawInstances=d}function Pg(n){const e={geometries:0,textures:0},t={frame:0,calls:0,triangles:0,points:0,lines:0};function a(r,s,o){switch(t.calls++,s){case n.TRIANGLES:t.triangles+=o*(r/3);break;case n.LINES:t.lines+=o*(r/2);break;case n.LINE_STRIP:t.lines+=o*(r-1);break;case n.LINE_LOOP:t.lines+=o*r;break;case n.POINTS:t.points+=o*r;break;default:console.error("THREE.WebGLInfo: Unknown draw mode:",s);break}}function i(){t.calls=0,t.triangles=0,t.points=0,t.lines=0}return{memory:e,render:t,programs:null,autoReset:!0,reset:i,update:a}}function Dg(n,e,t){const a=new WeakMap,i=new ot;function r(s,o,c){const l=s.morphTargetInfluences,h=o.morphAttributes.position||o.morphAttributes.normal||o.morphAttributes.color,d=h!==void 0?h.length:0;let f=a.get(o);if(f===void 0||f.count!==d){let w=function(){A.dispose(),a.delete(o),o.removeEventListener("dispose",w)};f!==void 0&&f.texture.dispose();const b=o.morphAttributes.position!==void 0,p=o.morphAttributes.normal!==void 0,g=o.morphAttributes.color!==void 0,m=o.morphAttributes.position||[],u=o.morphAttributes.normal||[],y=o.morphAttributes.color||[];let x=0;b===!0&&(x=1),p===!0&&(x=2),g===!0&&(x=3);let v=o.attributes.position.count*x,E=1;v>e.maxTextureSize&&(E=Math.ceil(v/e.maxTextureSize),v=e.maxTextureSize);const _=new Float32Array(v*E*4*d),A=new Zl(_,v,E,d);A.type=zt,A.needsUpdate=!0;const k=x*4;for(let M=0;M<d;M++){const R=m[M],U=u[M],P=y[M],D=v*E*4*M;for(let V=0;V<R.count;V++){const B=V*k;b===!0&&(i.fromBufferAttribute(R,V),_[D+B+0]=i.x,_[D+B+1]=i.y,_[D+B+2]=i.z,_[D+B+3]=0),p===!0&&(i.fromBufferAttribute(U,V),_[D+B+4]=i.x,_[D+B+5]=i.y,_[D+B+6]=i.z,_[D+B+7]=0),g===!0&&(i.fromBufferAttribute(P,V),_[D+B+8]=i.x,_[D+B+9]=i.y,_[D+B+10]=i.z,_[D+B+11]=P.itemSize===4?i.w:1)}}f={count:d,texture:A,size:new De(v,E)},a.set(o,f),o.addEventListener("dispose",w)}if(s.isInstancedMesh===!0&&s.morphTexture!==null)c.getUniforms().setValue(n,"morphTexture",s.morphTexture,t);else{let b=0;for(let g=0;g<l.length;g++)b+=l[g];const p=o.morphTargetsRelative?1:1-b;c.getUniforms().setValue(n,"morphTargetBaseInfluence",p),c.getUniforms().setValue(n,"morphTargetInfluences",l)}c.getUniforms().setValue(n,"morphTargetsTexture",f.texture,t),c.getUniforms().setValue(n,"morphTargetsTextureSize",f.size)}return{update:r}}function Ng(n,e,t,a){let i=new WeakMap;function r(c){const l=a.render.frame,h=c.geometry,d=e.get(c,h);if(i.get(d)!==l&&(e.update(d),i.set(d,l)),c.isInstancedMesh&&(c.hasEventListener("dispose",o)===!1&&c.addEventListener("dispose",o),i.get(c)!==l&&(t.update(c.instanceMatrix,n.ARRAY_BUFFER),c.instanceColor!==null&&t.update(c.instanceColor,n.ARRAY_BUFFER),i.set(c,l))),c.isSkinnedMesh){const f=c.skeleton;i.get(f)!==l&&(f.update(),i.set(f,l))}return d}function s(){i=new WeakMap}function o(c){const l=c.target;l.removeEventListener("dispose",o),t.remove(l.instanceMatrix),l.instanceColor!==null&&t.remove(l.instanceColor)}return{update:r,dispose:s}}class od extends _t{constructor(e,t,a,i,r,s,o,c,l,h=Dn){if(h!==Dn&&h!==On)throw new Error("DepthTexture format must be either THREE.DepthFormat or THREE.DepthStencilFormat");a===void 0&&h===Dn&&(a=sn),a===void 0&&h===On&&(a=jn),super(null,i,r,s,o,c,h,a,l),this.isDepthTexture=!0,this.image={width:e,height:t},this.magFilter=o!==void 0?o:dt,this.minFilter=c!==void 0?c:dt,this.flipY=!1,this.generateMipmaps=!1,this.compareFunction=null}copy(e){return super.copy(e),this.compareFunction=e.compareFunction,this}toJSON(e){const t=super.toJSON(e);return this.compareFunction!==null&&(t.compareFunction=this.compareFunction),t}}const cd=new _t,th=new od(1,1),hd=new Zl,ld=new xb,dd=new id,ah=[],nh=[],ih=new Float32Array(16),rh=new Float32Array(9),sh=new Float32Array(4);function Wn(n,e,t){const a=n[0];if(a<=0||a>0)return n;const i=e*t;let r=ah[i];if(r===void 0&&(r=new Float32Array(i),ah[i]=r),e!==0){a.toArray(r,0);for(let s=1,o=0;s!==e;++s)o+=t,n[s].toArray(r,o)}return r}function ft(n,e){if(n.length!==e.length)return!1;for(let t=0,a=n.length;t<a;t++)if(n[t]!==e[t])return!1;return!0}function ut(n,e){for(let t=0,a=e.length;t<a;t++)n[t]=e[t]}function Cr(n,e){let t=nh[e];t===void 0&&(t=new Int32Array(e),nh[e]=t);for(let a=0;a!==e;++a)t[a]=n.allocateTextureUnit();return t}function Ug(n,e){const t=this.cache;t[0]!==e&&(n.uniform1f(this.addr,e),t[0]=e)}function Fg(n,e){const t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y)&&(n.uniform2f(this.addr,e.x,e.y),t[0]=e.x,t[1]=e.y);else{if(ft(t,e))return;n.uniform2fv(this.addr,e),ut(t,e)}}function Lg(n,e){const t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z)&&(n.uniform3f(this.addr,e.x,e.y,e.z),t[0]=e.x,t[1]=e.y,t[2]=e.z);else if(e.r!==void 0)(t[0]!==e.r||t[1]!==e.g||t[2]!==e.b)&&(n.uniform3f(this.addr,e.r,e.g,e.b),t[0]=e.r,t[1]=e.g,t[2]=e.b);else{if(ft(t,e))return;n.uniform3fv(this.addr,e),ut(t,e)}}function jg(n,e){const t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z||t[3]!==e.w)&&(n.uniform4f(this.addr,e.x,e.y,e.z,e.w),t[0]=e.x,t[1]=e.y,t[2]=e.z,t[3]=e.w);else{if(ft(t,e))return;n.uniform4fv(this.addr,e),ut(t,e)}}function Og(n,e){const t=this.cache,a=e.elements;if(a===void 0){if(ft(t,e))return;n.uniformMatrix2fv(this.addr,!1,e),ut(t,e)}else{if(ft(t,a))return;sh.set(a),n.uniformMatrix2fv(this.addr,!1,sh),ut(t,a)}}function zg(n,e){const t=this.cache,a=e.elements;if(a===void 0){if(ft(t,e))return;n.uniformMatrix3fv(this.addr,!1,e),ut(t,e)}else{if(ft(t,a))return;rh.set(a),n.uniformMatrix3fv(this.addr,!1,rh),ut(t,a)}}function Bg(n,e){const t=this.cache,a=e.elements;if(a===void 0){if(ft(t,e))return;n.uniformMatrix4fv(this.addr,!1,e),ut(t,e)}else{if(ft(t,a))return;ih.set(a),n.uniformMatrix4fv(this.addr,!1,ih),ut(t,a)}}function Gg(n,e){const t=this.cache;t[0]!==e&&(n.uniform1i(this.addr,e),t[0]=e)}function Hg(n,e){const t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y)&&(n.uniform2i(this.addr,e.x,e.y),t[0]=e.x,t[1]=e.y);else{if(ft(t,e))return;n.uniform2iv(this.addr,e),ut(t,e)}}function Vg(n,e){const t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z)&&(n.uniform3i(this.addr,e.x,e.y,e.z),t[0]=e.x,t[1]=e.y,t[2]=e.z);else{if(ft(t,e))return;n.uniform3iv(this.addr,e),ut(t,e)}}function Wg(n,e){const t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z||t[3]!==e.w)&&(n.uniform4i(this.addr,e.x,e.y,e.z,e.w),t[0]=e.x,t[1]=e.y,t[2]=e.z,t[3]=e.w);else{if(ft(t,e))return;n.uniform4iv(this.addr,e),ut(t,e)}}function qg(n,e){const t=this.cache;t[0]!==e&&(n.uniform1ui(this.addr,e),t[0]=e)}function Xg(n,e){const t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y)&&(n.uniform2ui(this.addr,e.x,e.y),t[0]=e.x,t[1]=e.y);else{if(ft(t,e))return;n.uniform2uiv(this.addr,e),ut(t,e)}}function Kg(n,e){const t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z)&&(n.uniform3ui(this.addr,e.x,e.y,e.z),t[0]=e.x,t[1]=e.y,t[2]=e.z);else{if(ft(t,e))return;n.uniform3uiv(this.addr,e),ut(t,e)}}function Jg(n,e){const t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z||t[3]!==e.w)&&(n.uniform4ui(this.addr,e.x,e.y,e.z,e.w),t[0]=e.x,t[1]=e.y,t[2]=e.z,t[3]=e.w);else{if(ft(t,e))return;n.uniform4uiv(this.addr,e),ut(t,e)}}function Yg(n,e,t){const a=this.cache,i=t.allocateTextureUnit();a[0]!==i&&(n.uniform1i(this.addr,i),a[0]=i);let r;this.type===n.SAMPLER_2D_SHADOW?(th.compareFunction=ql,r=th):r=cd,t.setTexture2D(e||r,i)}function Zg(n,e,t){const a=this.cache,i=t.allocateTextureUnit();a[0]!==i&&(n.uniform1i(this.addr,i),a[0]=i),t.setTexture3D(e||ld,i)}function Qg(n,e,t){const a=this.cache,i=t.allocateTextureUnit();a[0]!==i&&(n.uniform1i(this.addr,i),a[0]=i),t.setTextureCube(e||dd,i)}function $g(n,e,t){const a=this.cache,i=t.allocateTextureUnit();a[0]!==i&&(n.uniform1i(this.addr,i),a[0]=i),t.setTexture2DArray(e||hd,i)}function ev(n){switch(n){case 5126:return Ug;case 35664:return Fg;case 35665:return Lg;case 35666:return jg;case 35674:return Og;case 35675:return zg;case 35676:return Bg;case 5124:case 35670:return Gg;case 35667:case 35671:return Hg;case 35668:case 35672:return Vg;case 35669:case 35673:return Wg;case 5125:return qg;case 36294:return Xg;case 36295:return Kg;case 36296:return Jg;case 35678:case 36198:case 36298:case 36306:case 35682:return Yg;case 35679:case 36299:case 36307:return Zg;case 35680:case 36300:case 36308:case 36293:return Qg;case 36289:case 36303:case 36311:case 36292:return $g}}function tv(n,e){n.uniform1fv(this.addr,e)}function av(n,e){const t=Wn(e,this.size,2);n.uniform2fv(this.addr,t)}function nv(n,e){const t=Wn(e,this.size,3);n.uniform3fv(this.addr,t)}function iv(n,e){const t=Wn(e,this.size,4);n.uniform4fv(this.addr,t)}function rv(n,e){const t=Wn(e,this.size,4);n.uniformMatrix2fv(this.addr,!1,t)}function sv(n,e){const t=Wn(e,this.size,9);n.uniformMatrix3fv(this.addr,!1,t)}function ov(n,e){const t=Wn(e,this.size,16);n.uniformMatrix4fv(this.addr,!1,t)}function cv(n,e){n.uniform1iv(this.addr,e)}function hv(n,e){n.uniform2iv(this.addr,e)}function lv(n,e){n.uniform3iv(this.addr,e)}function dv(n,e){n.uniform4iv(this.addr,e)}function fv(n,e){n.uniform1uiv(this.addr,e)}function uv(n,e){n.uniform2uiv(this.addr,e)}function bv(n,e){n.uniform3uiv(this.addr,e)}function mv(n,e){n.uniform4uiv(this.addr,e)}function pv(n,e,t){const a=this.cache,i=e.length,r=Cr(t,i);ft(a,r)||(n.uniform1iv(this.addr,r),ut(a,r));for(let s=0;s!==i;++s)t.setTexture2D(e[s]||cd,r[s])}function gv(n,e,t){const a=this.cache,i=e.length,r=Cr(t,i);ft(a,r)||(n.uniform1iv(this.addr,r),ut(a,r));for(let s=0;s!==i;++s)t.setTexture3D(e[s]||ld,r[s])}function vv(n,e,t){const a=this.cache,i=e.length,r=Cr(t,i);ft(a,r)||(n.uniform1iv(this.addr,r),ut(a,r));for(let s=0;s!==i;++s)t.setTextureCube(e[s]||dd,r[s])}function yv(n,e,t){const a=this.cache,i=e.length,r=Cr(t,i);ft(a,r)||(n.uniform1iv(this.addr,r),ut(a,r));for(let s=0;s!==i;++s)t.setTexture2DArray(e[s]||hd,r[s])}function xv(n){switch(n){case 5126:return tv;case 35664:return av;case 35665:return nv;case 35666:return iv;case 35674:return rv;case 35675:return sv;case 35676:return ov;case 5124:case 35670:return cv;case 35667:case 35671:return hv;case 35668:case 35672:return lv;case 35669:case 35673:return dv;case 5125:return fv;case 36294:return uv;case 36295:return bv;case 36296:return mv;case 35678:case 36198:case 36298:case 36306:case 35682:return pv;case 35679:case 36299:case 36307:return gv;case 35680:case 36300:case 36308:case 36293:return vv;case 36289:case 36303:case 36311:case 36292:return yv}}class wv{constructor(e,t,a){this.id=e,this.addr=a,this.cache=[],this.type=t.type,this.setValue=ev(t.type)}}class Mv{constructor(e,t,a){this.id=e,this.addr=a,this.cache=[],this.type=t.type,this.size=t.size,this.setValue=xv(t.type)}}class _v{constructor(e){this.id=e,this.seq=[],this.map={}}setValue(e,t,a){const i=this.seq;for(let r=0,s=i.length;r!==s;++r){const o=i[r];o.setValue(e,t[o.id],a)}}}const ls=/(\w+)(\])?(\[|\.)?/g;function oh(n,e){n.seq.push(e),n.map[e.id]=e}function Ev(n,e,t){const a=n.name,i=a.length;for(ls.lastIndex=0;;){const r=ls.exec(a),s=ls.lastIndex;let o=r[1];const c=r[2]==="]",l=r[3];if(c&&(o=o|0),l===void 0||l==="["&&s+2===i){oh(t,l===void 0?new wv(o,n,e):new Mv(o,n,e));break}else{let d=t.map[o];d===void 0&&(d=new _v(o),oh(t,d)),t=d}}}class dr{constructor(e,t){this.seq=[],this.map={};const a=e.getProgramParameter(t,e.ACTIVE_UNIFORMS);for(let i=0;i<a;++i){const r=e.getActiveUniform(t,i),s=e.getUniformLocation(t,r.name);Ev(r,s,this)}}setValue(e,t,a,i){const r=this.map[t];r!==void 0&&r.setValue(e,a,i)}setOptional(e,t,a){const i=t[a];i!==void 0&&this.setValue(e,a,i)}static upload(e,t,a,i){for(let r=0,s=t.length;r!==s;++r){const o=t[r],c=a[o.id];c.needsUpdate!==!1&&o.setValue(e,c.value,i)}}static seqWithValue(e,t){const a=[];for(let i=0,r=e.length;i!==r;++i){const s=e[i];s.id in t&&a.push(s)}return a}}function ch(n,e,t){const a=n.createShader(e);return n.shaderSource(a,t),n.compileShader(a),a}const Sv=37297;let Av=0;function Tv(n,e){const t=n.split(`
`),a=[],i=Math.max(e-6,0),r=Math.min(e+6,t.length);for(let s=i;s<r;s++){const o=s+1;a.push(`${o===e?">":" "} ${o}: ${t[s]}`)}return a.join(`
`)}const hh=new Pe;function kv(n){qe._getMatrix(hh,qe.workingColorSpace,n);const e=`mat3( ${hh.elements.map(t=>t.toFixed(4))} )`;switch(qe.getTransfer(n)){case Rr:return[e,"LinearTransferOETF"];case et:return[e,"sRGBTransferOETF"];default:return console.warn("THREE.WebGLProgram: Unsupported color space: ",n),[e,"LinearTransferOETF"]}}function lh(n,e,t){const a=n.getShaderParameter(e,n.COMPILE_STATUS),i=n.getShaderInfoLog(e).trim();if(a&&i==="")return"";const r=/ERROR: 0:(\d+)/.exec(i);if(r){const s=parseInt(r[1]);return t.toUpperCase()+`

`+i+`

`+Tv(n.getShaderSource(e),s)}else return i}function Rv(n,e){const t=kv(e);return[`vec4 ${n}( vec4 value ) {`,`	return ${t[1]}( vec4( value.rgb * ${t[0]}, value.a ) );`,"}"].join(`
`)}function Cv(n,e){let t;switch(e){case Pu:t="Linear";break;case Du:t="Reinhard";break;case Nu:t="Cineon";break;case Uu:t="ACESFilmic";break;case Lu:t="AgX";break;case ju:t="Neutral";break;case Fu:t="Custom";break;default:console.warn("THREE.WebGLProgram: Unsupported toneMapping:",e),t="Linear"}return"vec3 "+n+"( vec3 color ) { return "+t+"ToneMapping( color ); }"}const Yi=new O;function Iv(){qe.getLuminanceCoefficients(Yi);const n=Yi.x.toFixed(4),e=Yi.y.toFixed(4),t=Yi.z.toFixed(4);return["float luminance( const in vec3 rgb ) {",`	const vec3 weights = vec3( ${n}, ${e}, ${t} );`,"	return dot( weights, rgb );","}"].join(`
`)}function Pv(n){return[n.extensionClipCullDistance?"#extension GL_ANGLE_clip_cull_distance : require":"",n.extensionMultiDraw?"#extension GL_ANGLE_multi_draw : require":""].filter(li).join(`
`)}function Dv(n){const e=[];for(const t in n){const a=n[t];a!==!1&&e.push("#define "+t+" "+a)}return e.join(`
`)}function Nv(n,e){const t={},a=n.getProgramParameter(e,n.ACTIVE_ATTRIBUTES);for(let i=0;i<a;i++){const r=n.getActiveAttrib(e,i),s=r.name;let o=1;r.type===n.FLOAT_MAT2&&(o=2),r.type===n.FLOAT_MAT3&&(o=3),r.type===n.FLOAT_MAT4&&(o=4),t[s]={type:r.type,location:n.getAttribLocation(e,s),locationSize:o}}return t}function li(n){return n!==""}function dh(n,e){const t=e.numSpotLightShadows+e.numSpotLightMaps-e.numSpotLightShadowsWithMaps;return n.replace(/NUM_DIR_LIGHTS/g,e.numDirLights).replace(/NUM_SPOT_LIGHTS/g,e.numSpotLights).replace(/NUM_SPOT_LIGHT_MAPS/g,e.numSpotLightMaps).replace(/NUM_SPOT_LIGHT_COORDS/g,t).replace(/NUM_RECT_AREA_LIGHTS/g,e.numRectAreaLights).replace(/NUM_POINT_LIGHTS/g,e.numPointLights).replace(/NUM_HEMI_LIGHTS/g,e.numHemiLights).replace(/NUM_DIR_LIGHT_SHADOWS/g,e.numDirLightShadows).replace(/NUM_SPOT_LIGHT_SHADOWS_WITH_MAPS/g,e.numSpotLightShadowsWithMaps).replace(/NUM_SPOT_LIGHT_SHADOWS/g,e.numSpotLightShadows).replace(/NUM_POINT_LIGHT_SHADOWS/g,e.numPointLightShadows)}function fh(n,e){return n.replace(/NUM_CLIPPING_PLANES/g,e.numClippingPlanes).replace(/UNION_CLIPPING_PLANES/g,e.numClippingPlanes-e.numClipIntersection)}const Uv=/^[ \t]*#include +<([\w\d./]+)>/gm;function go(n){return n.replace(Uv,Lv)}const Fv=new Map;function Lv(n,e){let t=Le[e];if(t===void 0){const a=Fv.get(e);if(a!==void 0)t=Le[a],console.warn('THREE.WebGLRenderer: Shader chunk "%s" has been deprecated. Use "%s" instead.',e,a);else throw new Error("Can not resolve #include <"+e+">")}return go(t)}const jv=/#pragma unroll_loop_start\s+for\s*\(\s*int\s+i\s*=\s*(\d+)\s*;\s*i\s*<\s*(\d+)\s*;\s*i\s*\+\+\s*\)\s*{([\s\S]+?)}\s+#pragma unroll_loop_end/g;function uh(n){return n.replace(jv,Ov)}function Ov(n,e,t,a){let i="";for(let r=parseInt(e);r<parseInt(t);r++)i+=a.replace(/\[\s*i\s*\]/g,"[ "+r+" ]").replace(/UNROLLED_LOOP_INDEX/g,r);return i}function bh(n){let e=`precision ${n.precision} float;
	precision ${n.precision} int;
	precision ${n.precision} sampler2D;
	precision ${n.precision} samplerCube;
	precision ${n.precision} sampler3D;
	precision ${n.precision} sampler2DArray;
	precision ${n.precision} sampler2DShadow;
	precision ${n.precision} samplerCubeShadow;
	precision ${n.precision} sampler2DArrayShadow;
	precision ${n.precision} isampler2D;
	precision ${n.precision} isampler3D;
	precision ${n.precision} isamplerCube;
	precision ${n.precision} isampler2DArray;
	precision ${n.precision} usampler2D;
	precision ${n.precision} usampler3D;
	precision ${n.precision} usamplerCube;
	precision ${n.precision} usampler2DArray;
	`;return n.precision==="highp"?e+=`
#define HIGH_PRECISION`:n.precision==="mediump"?e+=`
#define MEDIUM_PRECISION`:n.precision==="lowp"&&(e+=`
#define LOW_PRECISION`),e}function zv(n){let e="SHADOWMAP_TYPE_BASIC";return n.shadowMapType===Pl?e="SHADOWMAP_TYPE_PCF":n.shadowMapType===du?e="SHADOWMAP_TYPE_PCF_SOFT":n.shadowMapType===pa&&(e="SHADOWMAP_TYPE_VSM"),e}function Bv(n){let e="ENVMAP_TYPE_CUBE";if(n.envMap)switch(n.envMapMode){case Fn:case Ln:e="ENVMAP_TYPE_CUBE";break;case kr:e="ENVMAP_TYPE_CUBE_UV";break}return e}function Gv(n){let e="ENVMAP_MODE_REFLECTION";return n.envMap&&n.envMapMode===Ln&&(e="ENVMAP_MODE_REFRACTION"),e}function Hv(n){let e="ENVMAP_BLENDING_NONE";if(n.envMap)switch(n.combine){case Dl:e="ENVMAP_BLENDING_MULTIPLY";break;case Cu:e="ENVMAP_BLENDING_MIX";break;case Iu:e="ENVMAP_BLENDING_ADD";break}return e}function Vv(n){const e=n.envMapCubeUVHeight;if(e===null)return null;const t=Math.log2(e)-2,a=1/e;return{texelWidth:1/(3*Math.max(Math.pow(2,t),112)),texelHeight:a,maxMip:t}}function Wv(n,e,t,a){const i=n.getContext(),r=t.defines;let s=t.vertexShader,o=t.fragmentShader;const c=zv(t),l=Bv(t),h=Gv(t),d=Hv(t),f=Vv(t),b=Pv(t),p=Dv(r),g=i.createProgram();let m,u,y=t.glslVersion?"#version "+t.glslVersion+`
`:"";t.isRawShaderMaterial?(m=["#define SHADER_TYPE "+t.shaderType,"#define SHADER_NAME "+t.shaderName,p].filter(li).join(`
`),m.length>0&&(m+=`
`),u=["#define SHADER_TYPE "+t.shaderType,"#define SHADER_NAME "+t.shaderName,p].filter(li).join(`
`),u.length>0&&(u+=`
`)):(m=[bh(t),"#define SHADER_TYPE "+t.shaderType,"#define SHADER_NAME "+t.shaderName,p,t.extensionClipCullDistance?"#define USE_CLIP_DISTANCE":"",t.batching?"#define USE_BATCHING":"",t.batchingColor?"#define USE_BATCHING_COLOR":"",t.instancing?"#define USE_INSTANCING":"",t.instancingColor?"#define USE_INSTANCING_COLOR":"",t.instancingMorph?"#define USE_INSTANCING_MORPH":"",t.useFog&&t.fog?"#define USE_FOG":"",t.useFog&&t.fogExp2?"#define FOG_EXP2":"",t.map?"#define USE_MAP":"",t.envMap?"#define USE_ENVMAP":"",t.envMap?"#define "+h:"",t.lightMap?"#define USE_LIGHTMAP":"",t.aoMap?"#define USE_AOMAP":"",t.bumpMap?"#define USE_BUMPMAP":"",t.normalMap?"#define USE_NORMALMAP":"",t.normalMapObjectSpace?"#define USE_NORMALMAP_OBJECTSPACE":"",t.normalMapTangentSpace?"#define USE_NORMALMAP_TANGENTSPACE":"",t.displacementMap?"#define USE_DISPLACEMENTMAP":"",t.emissiveMap?"#define USE_EMISSIVEMAP":"",t.anisotropy?"#define USE_ANISOTROPY":"",t.anisotropyMap?"#define USE_ANISOTROPYMAP":"",t.clearcoatMap?"#define USE_CLEARCOATMAP":"",t.clearcoatRoughnessMap?"#define USE_CLEARCOAT_ROUGHNESSMAP":"",t.clearcoatNormalMap?"#define USE_CLEARCOAT_NORMALMAP":"",t.iridescenceMap?"#define USE_IRIDESCENCEMAP":"",t.iridescenceThicknessMap?"#define USE_IRIDESCENCE_THICKNESSMAP":"",t.specularMap?"#define USE_SPECULARMAP":"",t.specularColorMap?"#define USE_SPECULAR_COLORMAP":"",t.specularIntensityMap?"#define USE_SPECULAR_INTENSITYMAP":"",t.roughnessMap?"#define USE_ROUGHNESSMAP":"",t.metalnessMap?"#define USE_METALNESSMAP":"",t.alphaMap?"#define USE_ALPHAMAP":"",t.alphaHash?"#define USE_ALPHAHASH":"",t.transmission?"#define USE_TRANSMISSION":"",t.transmissionMap?"#define USE_TRANSMISSIONMAP":"",t.thicknessMap?"#define USE_THICKNESSMAP":"",t.sheenColorMap?"#define USE_SHEEN_COLORMAP":"",t.sheenRoughnessMap?"#define USE_SHEEN_ROUGHNESSMAP":"",t.mapUv?"#define MAP_UV "+t.mapUv:"",t.alphaMapUv?"#define ALPHAMAP_UV "+t.alphaMapUv:"",t.lightMapUv?"#define LIGHTMAP_UV "+t.lightMapUv:"",t.aoMapUv?"#define AOMAP_UV "+t.aoMapUv:"",t.emissiveMapUv?"#define EMISSIVEMAP_UV "+t.emissiveMapUv:"",t.bumpMapUv?"#define BUMPMAP_UV "+t.bumpMapUv:"",t.normalMapUv?"#define NORMALMAP_UV "+t.normalMapUv:"",t.displacementMapUv?"#define DISPLACEMENTMAP_UV "+t.displacementMapUv:"",t.metalnessMapUv?"#define METALNESSMAP_UV "+t.metalnessMapUv:"",t.roughnessMapUv?"#define ROUGHNESSMAP_UV "+t.roughnessMapUv:"",t.anisotropyMapUv?"#define ANISOTROPYMAP_UV "+t.anisotropyMapUv:"",t.clearcoatMapUv?"#define CLEARCOATMAP_UV "+t.clearcoatMapUv:"",t.clearcoatNormalMapUv?"#define CLEARCOAT_NORMALMAP_UV "+t.clearcoatNormalMapUv:"",t.clearcoatRoughnessMapUv?"#define CLEARCOAT_ROUGHNESSMAP_UV "+t.clearcoatRoughnessMapUv:"",t.iridescenceMapUv?"#define IRIDESCENCEMAP_UV "+t.iridescenceMapUv:"",t.iridescenceThicknessMapUv?"#define IRIDESCENCE_THICKNESSMAP_UV "+t.iridescenceThicknessMapUv:"",t.sheenColorMapUv?"#define SHEEN_COLORMAP_UV "+t.sheenColorMapUv:"",t.sheenRoughnessMapUv?"#define SHEEN_ROUGHNESSMAP_UV "+t.sheenRoughnessMapUv:"",t.specularMapUv?"#define SPECULARMAP_UV "+t.specularMapUv:"",t.specularColorMapUv?"#define SPECULAR_COLORMAP_UV "+t.specularColorMapUv:"",t.specularIntensityMapUv?"#define SPECULAR_INTENSITYMAP_UV "+t.specularIntensityMapUv:"",t.transmissionMapUv?"#define TRANSMISSIONMAP_UV "+t.transmissionMapUv:"",t.thicknessMapUv?"#define THICKNESSMAP_UV "+t.thicknessMapUv:"",t.vertexTangents&&t.flatShading===!1?"#define USE_TANGENT":"",t.vertexColors?"#define USE_COLOR":"",t.vertexAlphas?"#define USE_COLOR_ALPHA":"",t.vertexUv1s?"#define USE_UV1":"",t.vertexUv2s?"#define USE_UV2":"",t.vertexUv3s?"#define USE_UV3":"",t.pointsUvs?"#define USE_POINTS_UV":"",t.flatShading?"#define FLAT_SHADED":"",t.skinning?"#define USE_SKINNING":"",t.morphTargets?"#define USE_MORPHTARGETS":"",t.morphNormals&&t.flatShading===!1?"#define USE_MORPHNORMALS":"",t.morphColors?"#define USE_MORPHCOLORS":"",t.morphTargetsCount>0?"#define MORPHTARGETS_TEXTURE_STRIDE "+t.morphTextureStride:"",t.morphTargetsCount>0?"#define MORPHTARGETS_COUNT "+t.morphTargetsCount:"",t.doubleSided?"#define DOUBLE_SIDED":"",t.flipSided?"#define FLIP_SIDED":"",t.shadowMapEnabled?"#define USE_SHADOWMAP":"",t.shadowMapEnabled?"#define "+c:"",t.sizeAttenuation?"#define USE_SIZEATTENUATION":"",t.numLightProbes>0?"#define USE_LIGHT_PROBES":"",t.logarithmicDepthBuffer?"#define USE_LOGDEPTHBUF":"",t.reverseDepthBuffer?"#define USE_REVERSEDEPTHBUF":"","uniform mat4 modelMatrix;","uniform mat4 modelViewMatrix;","uniform mat4 projectionMatrix;","uniform mat4 viewMatrix;","uniform mat3 normalMatrix;","uniform vec3 cameraPosition;","uniform bool isOrthographic;","#ifdef USE_INSTANCING","	attribute mat4 instanceMatrix;","#endif","#ifdef USE_INSTANCING_COLOR","	attribute vec3 instanceColor;","#endif","#ifdef USE_INSTANCING_MORPH","	uniform sampler2D morphTexture;","#endif","attribute vec3 position;","attribute vec3 normal;","attribute vec2 uv;","#ifdef USE_UV1","	attribute vec2 uv1;","#endif","#ifdef USE_UV2","	attribute vec2 uv2;","#endif","#ifdef USE_UV3","	attribute vec2 uv3;","#endif","#ifdef USE_TANGENT","	attribute vec4 tangent;","#endif","#if defined( USE_COLOR_ALPHA )","	attribute vec4 color;","#elif defined( USE_COLOR )","	attribute vec3 color;","#endif","#ifdef USE_SKINNING","	attribute vec4 skinIndex;","	attribute vec4 skinWeight;","#endif",`
`].filter(li).join(`
`),u=[bh(t),"#define SHADER_TYPE "+t.shaderType,"#define SHADER_NAME "+t.shaderName,p,t.useFog&&t.fog?"#define USE_FOG":"",t.useFog&&t.fogExp2?"#define FOG_EXP2":"",t.alphaToCoverage?"#define ALPHA_TO_COVERAGE":"",t.map?"#define USE_MAP":"",t.matcap?"#define USE_MATCAP":"",t.envMap?"#define USE_ENVMAP":"",t.envMap?"#define "+l:"",t.envMap?"#define "+h:"",t.envMap?"#define "+d:"",f?"#define CUBEUV_TEXEL_WIDTH "+f.texelWidth:"",f?"#define CUBEUV_TEXEL_HEIGHT "+f.texelHeight:"",f?"#define CUBEUV_MAX_MIP "+f.maxMip+".0":"",t.lightMap?"#define USE_LIGHTMAP":"",t.aoMap?"#define USE_AOMAP":"",t.bumpMap?"#define USE_BUMPMAP":"",t.normalMap?"#define USE_NORMALMAP":"",t.normalMapObjectSpace?"#define USE_NORMALMAP_OBJECTSPACE":"",t.normalMapTangentSpace?"#define USE_NORMALMAP_TANGENTSPACE":"",t.emissiveMap?"#define USE_EMISSIVEMAP":"",t.anisotropy?"#define USE_ANISOTROPY":"",t.anisotropyMap?"#define USE_ANISOTROPYMAP":"",t.clearcoat?"#define USE_CLEARCOAT":"",t.clearcoatMap?"#define USE_CLEARCOATMAP":"",t.clearcoatRoughnessMap?"#define USE_CLEARCOAT_ROUGHNESSMAP":"",t.clearcoatNormalMap?"#define USE_CLEARCOAT_NORMALMAP":"",t.dispersion?"#define USE_DISPERSION":"",t.iridescence?"#define USE_IRIDESCENCE":"",t.iridescenceMap?"#define USE_IRIDESCENCEMAP":"",t.iridescenceThicknessMap?"#define USE_IRIDESCENCE_THICKNESSMAP":"",t.specularMap?"#define USE_SPECULARMAP":"",t.specularColorMap?"#define USE_SPECULAR_COLORMAP":"",t.specularIntensityMap?"#define USE_SPECULAR_INTENSITYMAP":"",t.roughnessMap?"#define USE_ROUGHNESSMAP":"",t.metalnessMap?"#define USE_METALNESSMAP":"",t.alphaMap?"#define USE_ALPHAMAP":"",t.alphaTest?"#define USE_ALPHATEST":"",t.alphaHash?"#define USE_ALPHAHASH":"",t.sheen?"#define USE_SHEEN":"",t.sheenColorMap?"#define USE_SHEEN_COLORMAP":"",t.sheenRoughnessMap?"#define USE_SHEEN_ROUGHNESSMAP":"",t.transmission?"#define USE_TRANSMISSION":"",t.transmissionMap?"#define USE_TRANSMISSIONMAP":"",t.thicknessMap?"#define USE_THICKNESSMAP":"",t.vertexTangents&&t.flatShading===!1?"#define USE_TANGENT":"",t.vertexColors||t.instancingColor||t.batchingColor?"#define USE_COLOR":"",t.vertexAlphas?"#define USE_COLOR_ALPHA":"",t.vertexUv1s?"#define USE_UV1":"",t.vertexUv2s?"#define USE_UV2":"",t.vertexUv3s?"#define USE_UV3":"",t.pointsUvs?"#define USE_POINTS_UV":"",t.gradientMap?"#define USE_GRADIENTMAP":"",t.flatShading?"#define FLAT_SHADED":"",t.doubleSided?"#define DOUBLE_SIDED":"",t.flipSided?"#define FLIP_SIDED":"",t.shadowMapEnabled?"#define USE_SHADOWMAP":"",t.shadowMapEnabled?"#define "+c:"",t.premultipliedAlpha?"#define PREMULTIPLIED_ALPHA":"",t.numLightProbes>0?"#define USE_LIGHT_PROBES":"",t.decodeVideoTexture?"#define DECODE_VIDEO_TEXTURE":"",t.decodeVideoTextureEmissive?"#define DECODE_VIDEO_TEXTURE_EMISSIVE":"",t.logarithmicDepthBuffer?"#define USE_LOGDEPTHBUF":"",t.reverseDepthBuffer?"#define USE_REVERSEDEPTHBUF":"","uniform mat4 viewMatrix;","uniform vec3 cameraPosition;","uniform bool isOrthographic;",t.toneMapping!==Ha?"#define TONE_MAPPING":"",t.toneMapping!==Ha?Le.tonemapping_pars_fragment:"",t.toneMapping!==Ha?Cv("toneMapping",t.toneMapping):"",t.dithering?"#define DITHERING":"",t.opaque?"#define OPAQUE":"",Le.colorspace_pars_fragment,Rv("linearToOutputTexel",t.outputColorSpace),Iv(),t.useDepthPacking?"#define DEPTH_PACKING "+t.depthPacking:"",`
`].filter(li).join(`
`)),s=go(s),s=dh(s,t),s=fh(s,t),o=go(o),o=dh(o,t),o=fh(o,t),s=uh(s),o=uh(o),t.isRawShaderMaterial!==!0&&(y=`#version 300 es
`,m=[b,"#define attribute in","#define varying out","#define texture2D texture"].join(`
`)+`
`+m,u=["#define varying in",t.glslVersion===Ea?"":"layout(location = 0) out highp vec4 pc_fragColor;",t.glslVersion===Ea?"":"#define gl_FragColor pc_fragColor","#define gl_FragDepthEXT gl_FragDepth","#define texture2D texture","#define textureCube texture","#define texture2DProj textureProj","#define texture2DLodEXT textureLod","#define texture2DProjLodEXT textureProjLod","#define textureCubeLodEXT textureLod","#define texture2DGradEXT textureGrad","#define texture2DProjGradEXT textureProjGrad","#define textureCubeGradEXT textureGrad"].join(`
`)+`
`+u);const x=y+m+s,v=y+u+o,E=ch(i,i.VERTEX_SHADER,x),_=ch(i,i.FRAGMENT_SHADER,v);i.attachShader(g,E),i.attachShader(g,_),t.index0AttributeName!==void 0?i.bindAttribLocation(g,0,t.index0AttributeName):t.morphTargets===!0&&i.bindAttribLocation(g,0,"position"),i.linkProgram(g);function A(R){if(n.debug.checkShaderErrors){const U=i.getProgramInfoLog(g).trim(),P=i.getShaderInfoLog(E).trim(),D=i.getShaderInfoLog(_).trim();let V=!0,B=!0;if(i.getProgramParameter(g,i.LINK_STATUS)===!1)if(V=!1,typeof n.debug.onShaderError=="function")n.debug.onShaderError(i,g,E,_);else{const G=lh(i,E,"vertex"),z=lh(i,_,"fragment");console.error("THREE.WebGLProgram: Shader Error "+i.getError()+" - VALIDATE_STATUS "+i.getProgramParameter(g,i.VALIDATE_STATUS)+`

Material Name: `+R.name+`
Material Type: `+R.type+`

Program Info Log: `+U+`
`+G+`
`+z)}else U!==""?console.warn("THREE.WebGLProgram: Program Info Log:",U):(P===""||D==="")&&(B=!1);B&&(R.diagnostics={runnable:V,programLog:U,vertexShader:{log:P,prefix:m},fragmentShader:{log:D,prefix:u}})}i.deleteShader(E),i.deleteShader(_),k=new dr(i,g),w=Nv(i,g)}let k;this.getUniforms=function(){return k===void 0&&A(this),k};let w;this.getAttributes=function(){return w===void 0&&A(this),w};let M=t.rendererExtensionParallelShaderCompile===!1;return this.isReady=function(){return M===!1&&(M=i.getProgramParameter(g,Sv)),M},this.destroy=function(){a.releaseStatesOfProgram(this),i.deleteProgram(g),this.program=void 0},this.type=t.shaderType,this.name=t.shaderName,this.id=Av++,this.cacheKey=e,this.usedTimes=1,this.program=g,this.vertexShader=E,this.fragmentShader=_,this}let qv=0;class Xv{constructor(){this.shaderCache=new Map,this.materialCache=new Map}update(e){const t=e.vertexShader,a=e.fragmentShader,i=this._getShaderStage(t),r=this._getShaderStage(a),s=this._getShaderCacheForMaterial(e);return s.has(i)===!1&&(s.add(i),i.usedTimes++),s.has(r)===!1&&(s.add(r),r.usedTimes++),this}remove(e){const t=this.materialCache.get(e);for(const a of t)a.usedTimes--,a.usedTimes===0&&this.shaderCache.delete(a.code);return this.materialCache.delete(e),this}getVertexShaderID(e){return this._getShaderStage(e.vertexShader).id}getFragmentShaderID(e){return this._getShaderStage(e.fragmentShader).id}dispose(){this.shaderCache.clear(),this.materialCache.clear()}_getShaderCacheForMaterial(e){const t=this.materialCache;let a=t.get(e);return a===void 0&&(a=new Set,t.set(e,a)),a}_getShaderStage(e){const t=this.shaderCache;let a=t.get(e);return a===void 0&&(a=new Kv(e),t.set(e,a)),a}}class Kv{constructor(e){this.id=qv++,this.code=e,this.usedTimes=0}}function Jv(n,e,t,a,i,r,s){const o=new Ql,c=new Xv,l=new Set,h=[],d=i.logarithmicDepthBuffer,f=i.vertexTextures;let b=i.precision;const p={MeshDepthMaterial:"depth",MeshDistanceMaterial:"distanceRGBA",MeshNormalMaterial:"normal",MeshBasicMaterial:"basic",MeshLambertMaterial:"lambert",MeshPhongMaterial:"phong",MeshToonMaterial:"toon",MeshStandardMaterial:"physical",MeshPhysicalMaterial:"physical",MeshMatcapMaterial:"matcap",LineBasicMaterial:"basic",LineDashedMaterial:"dashed",PointsMaterial:"points",ShadowMaterial:"shadow",SpriteMaterial:"sprite"};function g(w){return l.add(w),w===0?"uv":`uv${w}`}function m(w,M,R,U,P){const D=U.fog,V=P.geometry,B=w.isMeshStandardMaterial?U.environment:null,G=(w.isMeshStandardMaterial?t:e).get(w.envMap||B),z=G&&G.mapping===kr?G.image.height:null,Y=p[w.type];w.precision!==null&&(b=i.getMaxPrecision(w.precision),b!==w.precision&&console.warn("THREE.WebGLProgram.getParameters:",w.precision,"not supported, using",b,"instead."));const te=V.morphAttributes.position||V.morphAttributes.normal||V.morphAttributes.color,ie=te!==void 0?te.length:0;let pe=0;V.morphAttributes.position!==void 0&&(pe=1),V.morphAttributes.normal!==void 0&&(pe=2),V.morphAttributes.color!==void 0&&(pe=3);let Te,W,J,se;if(Y){const Qe=sa[Y];Te=Qe.vertexShader,W=Qe.fragmentShader}else Te=w.vertexShader,W=w.fragmentShader,c.update(w),J=c.getVertexShaderID(w),se=c.getFragmentShaderID(w);const re=n.getRenderTarget(),ge=n.state.buffers.depth.getReversed(),Ae=P.isInstancedMesh===!0,Re=P.isBatchedMesh===!0,We=!!w.map,Ie=!!w.matcap,Ke=!!G,F=!!w.aoMap,vt=!!w.lightMap,je=!!w.bumpMap,Oe=!!w.normalMap,Ee=!!w.displacementMap,Ze=!!w.emissiveMap,_e=!!w.metalnessMap,C=!!w.roughnessMap,S=w.anisotropy>0,H=w.clearcoat>0,Q=w.dispersion>0,ee=w.iridescence>0,Z=w.sheen>0,ve=w.transmission>0,ce=S&&!!w.anisotropyMap,be=H&&!!w.clearcoatMap,Ge=H&&!!w.clearcoatNormalMap,ae=H&&!!w.clearcoatRoughnessMap,me=ee&&!!w.iridescenceMap,Se=ee&&!!w.iridescenceThicknessMap,ke=Z&&!!w.sheenColorMap,ue=Z&&!!w.sheenRoughnessMap,He=!!w.specularMap,Fe=!!w.specularColorMap,at=!!w.specularIntensityMap,N=ve&&!!w.transmissionMap,he=ve&&!!w.thicknessMap,K=!!w.gradientMap,$=!!w.alphaMap,fe=w.alphaTest>0,le=!!w.alphaHash,Ne=!!w.extensions;let ct=Ha;w.toneMapped&&(re===null||re.isXRRenderTarget===!0)&&(ct=n.toneMapping);const yt={shaderID:Y,shaderType:w.type,shaderName:w.name,vertexShader:Te,fragmentShader:W,defines:w.defines,customVertexShaderID:J,customFragmentShaderID:se,isRawShaderMaterial:w.isRawShaderMaterial===!0,glslVersion:w.glslVersion,precision:b,batching:Re,batchingColor:Re&&P._colorsTexture!==null,instancing:Ae,instancingColor:Ae&&P.instanceColor!==null,instancingMorph:Ae&&P.morphTexture!==null,supportsVertexTextures:f,outputColorSpace:re===null?n.outputColorSpace:re.isXRRenderTarget===!0?re.texture.colorSpace:Hn,alphaToCoverage:!!w.alphaToCoverage,map:We,matcap:Ie,envMap:Ke,envMapMode:Ke&&G.mapping,envMapCubeUVHeight:z,aoMap:F,lightMap:vt,bumpMap:je,normalMap:Oe,displacementMap:f&&Ee,emissiveMap:Ze,normalMapObjectSpace:Oe&&w.normalMapType===Gu,normalMapTangentSpace:Oe&&w.normalMapType===Bu,metalnessMap:_e,roughnessMap:C,anisotropy:S,anisotropyMap:ce,clearcoat:H,clearcoatMap:be,clearcoatNormalMap:Ge,clearcoatRoughnessMap:ae,dispersion:Q,iridescence:ee,iridescenceMap:me,iridescenceThicknessMap:Se,sheen:Z,sheenColorMap:ke,sheenRoughnessMap:ue,specularMap:He,specularColorMap:Fe,specularIntensityMap:at,transmission:ve,transmissionMap:N,thicknessMap:he,gradientMap:K,opaque:w.transparent===!1&&w.blending===Pn&&w.alphaToCoverage===!1,alphaMap:$,alphaTest:fe,alphaHash:le,combine:w.combine,mapUv:We&&g(w.map.channel),aoMapUv:F&&g(w.aoMap.channel),lightMapUv:vt&&g(w.lightMap.channel),bumpMapUv:je&&g(w.bumpMap.channel),normalMapUv:Oe&&g(w.normalMap.channel),displacementMapUv:Ee&&g(w.displacementMap.channel),emissiveMapUv:Ze&&g(w.emissiveMap.channel),metalnessMapUv:_e&&g(w.metalnessMap.channel),roughnessMapUv:C&&g(w.roughnessMap.channel),anisotropyMapUv:ce&&g(w.anisotropyMap.channel),clearcoatMapUv:be&&g(w.clearcoatMap.channel),clearcoatNormalMapUv:Ge&&g(w.clearcoatNormalMap.channel),clearcoatRoughnessMapUv:ae&&g(w.clearcoatRoughnessMap.channel),iridescenceMapUv:me&&g(w.iridescenceMap.channel),iridescenceThicknessMapUv:Se&&g(w.iridescenceThicknessMap.channel),sheenColorMapUv:ke&&g(w.sheenColorMap.channel),sheenRoughnessMapUv:ue&&g(w.sheenRoughnessMap.channel),specularMapUv:He&&g(w.specularMap.channel),specularColorMapUv:Fe&&g(w.specularColorMap.channel),specularIntensityMapUv:at&&g(w.specularIntensityMap.channel),transmissionMapUv:N&&g(w.transmissionMap.channel),thicknessMapUv:he&&g(w.thicknessMap.channel),alphaMapUv:$&&g(w.alphaMap.channel),vertexTangents:!!V.attributes.tangent&&(Oe||S),vertexColors:w.vertexColors,vertexAlphas:w.vertexColors===!0&&!!V.attributes.color&&V.attributes.color.itemSize===4,pointsUvs:P.isPoints===!0&&!!V.attributes.uv&&(We||$),fog:!!D,useFog:w.fog===!0,fogExp2:!!D&&D.isFogExp2,flatShading:w.flatShading===!0,sizeAttenuation:w.sizeAttenuation===!0,logarithmicDepthBuffer:d,reverseDepthBuffer:ge,skinning:P.isSkinnedMesh===!0,morphTargets:V.morphAttributes.position!==void 0,morphNormals:V.morphAttributes.normal!==void 0,morphColors:V.morphAttributes.color!==void 0,morphTargetsCount:ie,morphTextureStride:pe,numDirLights:M.directional.length,numPointLights:M.point.length,numSpotLights:M.spot.length,numSpotLightMaps:M.spotLightMap.length,numRectAreaLights:M.rectArea.length,numHemiLights:M.hemi.length,numDirLightShadows:M.directionalShadowMap.length,numPointLightShadows:M.pointShadowMap.length,numSpotLightShadows:M.spotShadowMap.length,numSpotLightShadowsWithMaps:M.numSpotLightShadowsWithMaps,numLightProbes:M.numLightProbes,numClippingPlanes:s.numPlanes,numClipIntersection:s.numIntersection,dithering:w.dithering,shadowMapEnabled:n.shadowMap.enabled&&R.length>0,shadowMapType:n.shadowMap.type,toneMapping:ct,decodeVideoTexture:We&&w.map.isVideoTexture===!0&&qe.getTransfer(w.map.colorSpace)===et,decodeVideoTextureEmissive:Ze&&w.emissiveMap.isVideoTexture===!0&&qe.getTransfer(w.emissiveMap.colorSpace)===et,premultipliedAlpha:w.premultipliedAlpha,doubleSided:w.side===Kt,flipSided:w.side===Ut,useDepthPacking:w.depthPacking>=0,depthPacking:w.depthPacking||0,index0AttributeName:w.index0AttributeName,extensionClipCullDistance:Ne&&w.extensions.clipCullDistance===!0&&a.has("WEBGL_clip_cull_distance"),extensionMultiDraw:(Ne&&w.extensions.multiDraw===!0||Re)&&a.has("WEBGL_multi_draw"),rendererExtensionParallelShaderCompile:a.has("KHR_parallel_shader_compile"),customProgramCacheKey:w.customProgramCacheKey()};return yt.vertexUv1s=l.has(1),yt.vertexUv2s=l.has(2),yt.vertexUv3s=l.has(3),l.clear(),yt}function u(w){const M=[];if(w.shaderID?M.push(w.shaderID):(M.push(w.customVertexShaderID),M.push(w.customFragmentShaderID)),w.defines!==void 0)for(const R in w.defines)M.push(R),M.push(w.defines[R]);return w.isRawShaderMaterial===!1&&(y(M,w),x(M,w),M.push(n.outputColorSpace)),M.push(w.customProgramCacheKey),M.join()}function y(w,M){w.push(M.precision),w.push(M.outputColorSpace),w.push(M.envMapMode),w.push(M.envMapCubeUVHeight),w.push(M.mapUv),w.push(M.alphaMapUv),w.push(M.lightMapUv),w.push(M.aoMapUv),w.push(M.bumpMapUv),w.push(M.normalMapUv),w.push(M.displacementMapUv),w.push(M.emissiveMapUv),w.push(M.metalnessMapUv),w.push(M.roughnessMapUv),w.push(M.anisotropyMapUv),w.push(M.clearcoatMapUv),w.push(M.clearcoatNormalMapUv),w.push(M.clearcoatRoughnessMapUv),w.push(M.iridescenceMapUv),w.push(M.iridescenceThicknessMapUv),w.push(M.sheenColorMapUv),w.push(M.sheenRoughnessMapUv),w.push(M.specularMapUv),w.push(M.specularColorMapUv),w.push(M.specularIntensityMapUv),w.push(M.transmissionMapUv),w.push(M.thicknessMapUv),w.push(M.combine),w.push(M.fogExp2),w.push(M.sizeAttenuation),w.push(M.morphTargetsCount),w.push(M.morphAttributeCount),w.push(M.numDirLights),w.push(M.numPointLights),w.push(M.numSpotLights),w.push(M.numSpotLightMaps),w.push(M.numHemiLights),w.push(M.numRectAreaLights),w.push(M.numDirLightShadows),w.push(M.numPointLightShadows),w.push(M.numSpotLightShadows),w.push(M.numSpotLightShadowsWithMaps),w.push(M.numLightProbes),w.push(M.shadowMapType),w.push(M.toneMapping),w.push(M.numClippingPlanes),w.push(M.numClipIntersection),w.push(M.depthPacking)}function x(w,M){o.disableAll(),M.supportsVertexTextures&&o.enable(0),M.instancing&&o.enable(1),M.instancingColor&&o.enable(2),M.instancingMorph&&o.enable(3),M.matcap&&o.enable(4),M.envMap&&o.enable(5),M.normalMapObjectSpace&&o.enable(6),M.normalMapTangentSpace&&o.enable(7),M.clearcoat&&o.enable(8),M.iridescence&&o.enable(9),M.alphaTest&&o.enable(10),M.vertexColors&&o.enable(11),M.vertexAlphas&&o.enable(12),M.vertexUv1s&&o.enable(13),M.vertexUv2s&&o.enable(14),M.vertexUv3s&&o.enable(15),M.vertexTangents&&o.enable(16),M.anisotropy&&o.enable(17),M.alphaHash&&o.enable(18),M.batching&&o.enable(19),M.dispersion&&o.enable(20),M.batchingColor&&o.enable(21),w.push(o.mask),o.disableAll(),M.fog&&o.enable(0),M.useFog&&o.enable(1),M.flatShading&&o.enable(2),M.logarithmicDepthBuffer&&o.enable(3),M.reverseDepthBuffer&&o.enable(4),M.skinning&&o.enable(5),M.morphTargets&&o.enable(6),M.morphNormals&&o.enable(7),M.morphColors&&o.enable(8),M.premultipliedAlpha&&o.enable(9),M.shadowMapEnabled&&o.enable(10),M.doubleSided&&o.enable(11),M.flipSided&&o.enable(12),M.useDepthPacking&&o.enable(13),M.dithering&&o.enable(14),M.transmission&&o.enable(15),M.sheen&&o.enable(16),M.opaque&&o.enable(17),M.pointsUvs&&o.enable(18),M.decodeVideoTexture&&o.enable(19),M.decodeVideoTextureEmissive&&o.enable(20),M.alphaToCoverage&&o.enable(21),w.push(o.mask)}function v(w){const M=p[w.type];let R;if(M){const U=sa[M];R=Pb.clone(U.uniforms)}else R=w.uniforms;return R}function E(w,M){let R;for(let U=0,P=h.length;U<P;U++){const D=h[U];if(D.cacheKey===M){R=D,++R.usedTimes;break}}return R===void 0&&(R=new Wv(n,M,w,r),h.push(R)),R}function _(w){if(--w.usedTimes===0){const M=h.indexOf(w);h[M]=h[h.length-1],h.pop(),w.destroy()}}function A(w){c.remove(w)}function k(){c.dispose()}return{getParameters:m,getProgramCacheKey:u,getUniforms:v,acquireProgram:E,releaseProgram:_,releaseShaderCache:A,programs:h,dispose:k}}function Yv(){let n=new WeakMap;function e(s){return n.has(s)}function t(s){let o=n.get(s);return o===void 0&&(o={},n.set(s,o)),o}function a(s){n.delete(s)}function i(s,o,c){n.get(s)[o]=c}function r(){n=new WeakMap}return{has:e,get:t,remove:a,update:i,dispose:r}}function Zv(n,e){return n.groupOrder!==e.groupOrder?n.groupOrder-e.groupOrder:n.renderOrder!==e.renderOrder?n.renderOrder-e.renderOrder:n.material.id!==e.material.id?n.material.id-e.material.id:n.z!==e.z?n.z-e.z:n.id-e.id}function mh(n,e){return n.groupOrder!==e.groupOrder?n.groupOrder-e.groupOrder:n.renderOrder!==e.renderOrder?n.renderOrder-e.renderOrder:n.z!==e.z?e.z-n.z:n.id-e.id}function ph(){const n=[];let e=0;const t=[],a=[],i=[];function r(){e=0,t.length=0,a.length=0,i.length=0}function s(d,f,b,p,g,m){let u=n[e];return u===void 0?(u={id:d.id,object:d,geometry:f,material:b,groupOrder:p,renderOrder:d.renderOrder,z:g,group:m},n[e]=u):(u.id=d.id,u.object=d,u.geometry=f,u.material=b,u.groupOrder=p,u.renderOrder=d.renderOrder,u.z=g,u.group=m),e++,u}function o(d,f,b,p,g,m){const u=s(d,f,b,p,g,m);b.transmission>0?a.push(u):b.transparent===!0?i.push(u):t.push(u)}function c(d,f,b,p,g,m){const u=s(d,f,b,p,g,m);b.transmission>0?a.unshift(u):b.transparent===!0?i.unshift(u):t.unshift(u)}function l(d,f){t.length>1&&t.sort(d||Zv),a.length>1&&a.sort(f||mh),i.length>1&&i.sort(f||mh)}function h(){for(let d=e,f=n.length;d<f;d++){const b=n[d];if(b.id===null)break;b.id=null,b.object=null,b.geometry=null,b.material=null,b.group=null}}return{opaque:t,transmissive:a,transparent:i,init:r,push:o,unshift:c,finish:h,sort:l}}function Qv(){let n=new WeakMap;function e(a,i){const r=n.get(a);let s;return r===void 0?(s=new ph,n.set(a,[s])):i>=r.length?(s=new ph,r.push(s)):s=r[i],s}function t(){n=new WeakMap}return{get:e,dispose:t}}function $v(){const n={};return{get:function(e){if(n[e.id]!==void 0)return n[e.id];let t;switch(e.type){case"DirectionalLight":t={direction:new O,color:new Ve};break;case"SpotLight":t={position:new O,direction:new O,color:new Ve,distance:0,coneCos:0,penumbraCos:0,decay:0};break;case"PointLight":t={position:new O,color:new Ve,distance:0,decay:0};break;case"HemisphereLight":t={direction:new O,skyColor:new Ve,groundColor:new Ve};break;case"RectAreaLight":t={color:new Ve,position:new O,halfWidth:new O,halfHeight:new O};break}return n[e.id]=t,t}}}function ey(){const n={};return{get:function(e){if(n[e.id]!==void 0)return n[e.id];let t;switch(e.type){case"DirectionalLight":t={shadowIntensity:1,shadowBias:0,shadowNormalBias:0,shadowRadius:1,shadowMapSize:new De};break;case"SpotLight":t={shadowIntensity:1,shadowBias:0,shadowNormalBias:0,shadowRadius:1,shadowMapSize:new De};break;case"PointLight":t={shadowIntensity:1,shadowBias:0,shadowNormalBias:0,shadowRadius:1,shadowMapSize:new De,shadowCameraNear:1,shadowCameraFar:1e3};break}return n[e.id]=t,t}}}let ty=0;function ay(n,e){return(e.castShadow?2:0)-(n.castShadow?2:0)+(e.map?1:0)-(n.map?1:0)}function ny(n){const e=new $v,t=ey(),a={version:0,hash:{directionalLength:-1,pointLength:-1,spotLength:-1,rectAreaLength:-1,hemiLength:-1,numDirectionalShadows:-1,numPointShadows:-1,numSpotShadows:-1,numSpotMaps:-1,numLightProbes:-1},ambient:[0,0,0],probe:[],directional:[],directionalShadow:[],directionalShadowMap:[],directionalShadowMatrix:[],spot:[],spotLightMap:[],spotShadow:[],spotShadowMap:[],spotLightMatrix:[],rectArea:[],rectAreaLTC1:null,rectAreaLTC2:null,point:[],pointShadow:[],pointShadowMap:[],pointShadowMatrix:[],hemi:[],numSpotLightShadowsWithMaps:0,numLightProbes:0};for(let l=0;l<9;l++)a.probe.push(new O);const i=new O,r=new ze,s=new ze;function o(l){let h=0,d=0,f=0;for(let w=0;w<9;w++)a.probe[w].set(0,0,0);let b=0,p=0,g=0,m=0,u=0,y=0,x=0,v=0,E=0,_=0,A=0;l.sort(ay);for(let w=0,M=l.length;w<M;w++){const R=l[w],U=R.color,P=R.intensity,D=R.distance,V=R.shadow&&R.shadow.map?R.shadow.map.texture:null;if(R.isAmbientLight)h+=U.r*P,d+=U.g*P,f+=U.b*P;else if(R.isLightProbe){for(let B=0;B<9;B++)a.probe[B].addScaledVector(R.sh.coefficients[B],P);A++}else if(R.isDirectionalLight){const B=e.get(R);if(B.color.copy(R.color).multiplyScalar(R.intensity),R.castShadow){const G=R.shadow,z=t.get(R);z.shadowIntensity=G.intensity,z.shadowBias=G.bias,z.shadowNormalBias=G.normalBias,z.shadowRadius=G.radius,z.shadowMapSize=G.mapSize,a.directionalShadow[b]=z,a.directionalShadowMap[b]=V,a.directionalShadowMatrix[b]=R.shadow.matrix,y++}a.directional[b]=B,b++}else if(R.isSpotLight){const B=e.get(R);B.position.setFromMatrixPosition(R.matrixWorld),B.color.copy(U).multiplyScalar(P),B.distance=D,B.coneCos=Math.cos(R.angle),B.penumbraCos=Math.cos(R.angle*(1-R.penumbra)),B.decay=R.decay,a.spot[g]=B;const G=R.shadow;if(R.map&&(a.spotLightMap[E]=R.map,E++,G.updateMatrices(R),R.castShadow&&_++),a.spotLightMatrix[g]=G.matrix,R.castShadow){const z=t.get(R);z.shadowIntensity=G.intensity,z.shadowBias=G.bias,z.shadowNormalBias=G.normalBias,z.shadowRadius=G.radius,z.shadowMapSize=G.mapSize,a.spotShadow[g]=z,a.spotShadowMap[g]=V,v++}g++}else if(R.isRectAreaLight){const B=e.get(R);B.color.copy(U).multiplyScalar(P),B.halfWidth.set(R.width*.5,0,0),B.halfHeight.set(0,R.height*.5,0),a.rectArea[m]=B,m++}else if(R.isPointLight){const B=e.get(R);if(B.color.copy(R.color).multiplyScalar(R.intensity),B.distance=R.distance,B.decay=R.decay,R.castShadow){const G=R.shadow,z=t.get(R);z.shadowIntensity=G.intensity,z.shadowBias=G.bias,z.shadowNormalBias=G.normalBias,z.shadowRadius=G.radius,z.shadowMapSize=G.mapSize,z.shadowCameraNear=G.camera.near,z.shadowCameraFar=G.camera.far,a.pointShadow[p]=z,a.pointShadowMap[p]=V,a.pointShadowMatrix[p]=R.shadow.matrix,x++}a.point[p]=B,p++}else if(R.isHemisphereLight){const B=e.get(R);B.skyColor.copy(R.color).multiplyScalar(P),B.groundColor.copy(R.groundColor).multiplyScalar(P),a.hemi[u]=B,u++}}m>0&&(n.has("OES_texture_float_linear")===!0?(a.rectAreaLTC1=oe.LTC_FLOAT_1,a.rectAreaLTC2=oe.LTC_FLOAT_2):(a.rectAreaLTC1=oe.LTC_HALF_1,a.rectAreaLTC2=oe.LTC_HALF_2)),a.ambient[0]=h,a.ambient[1]=d,a.ambient[2]=f;const k=a.hash;(k.directionalLength!==b||k.pointLength!==p||k.spotLength!==g||k.rectAreaLength!==m||k.hemiLength!==u||k.numDirectionalShadows!==y||k.numPointShadows!==x||k.numSpotShadows!==v||k.numSpotMaps!==E||k.numLightProbes!==A)&&(a.directional.length=b,a.spot.length=g,a.rectArea.length=m,a.point.length=p,a.hemi.length=u,a.directionalShadow.length=y,a.directionalShadowMap.length=y,a.pointShadow.length=x,a.pointShadowMap.length=x,a.spotShadow.length=v,a.spotShadowMap.length=v,a.directionalShadowMatrix.length=y,a.pointShadowMatrix.length=x,a.spotLightMatrix.length=v+E-_,a.spotLightMap.length=E,a.numSpotLightShadowsWithMaps=_,a.numLightProbes=A,k.directionalLength=b,k.pointLength=p,k.spotLength=g,k.rectAreaLength=m,k.hemiLength=u,k.numDirectionalShadows=y,k.numPointShadows=x,k.numSpotShadows=v,k.numSpotMaps=E,k.numLightProbes=A,a.version=ty++)}function c(l,h){let d=0,f=0,b=0,p=0,g=0;const m=h.matrixWorldInverse;for(let u=0,y=l.length;u<y;u++){const x=l[u];if(x.isDirectionalLight){const v=a.directional[d];v.direction.setFromMatrixPosition(x.matrixWorld),i.setFromMatrixPosition(x.target.matrixWorld),v.direction.sub(i),v.direction.transformDirection(m),d++}else if(x.isSpotLight){const v=a.spot[b];v.position.setFromMatrixPosition(x.matrixWorld),v.position.applyMatrix4(m),v.direction.setFromMatrixPosition(x.matrixWorld),i.setFromMatrixPosition(x.target.matrixWorld),v.direction.sub(i),v.direction.transformDirection(m),b++}else if(x.isRectAreaLight){const v=a.rectArea[p];v.position.setFromMatrixPosition(x.matrixWorld),v.position.applyMatrix4(m),s.identity(),r.copy(x.matrixWorld),r.premultiply(m),s.extractRotation(r),v.halfWidth.set(x.width*.5,0,0),v.halfHeight.set(0,x.height*.5,0),v.halfWidth.applyMatrix4(s),v.halfHeight.applyMatrix4(s),p++}else if(x.isPointLight){const v=a.point[f];v.position.setFromMatrixPosition(x.matrixWorld),v.position.applyMatrix4(m),f++}else if(x.isHemisphereLight){const v=a.hemi[g];v.direction.setFromMatrixPosition(x.matrixWorld),v.direction.transformDirection(m),g++}}}return{setup:o,setupView:c,state:a}}function gh(n){const e=new ny(n),t=[],a=[];function i(h){l.camera=h,t.length=0,a.length=0}function r(h){t.push(h)}function s(h){a.push(h)}function o(){e.setup(t)}function c(h){e.setupView(t,h)}const l={lightsArray:t,shadowsArray:a,camera:null,lights:e,transmissionRenderTarget:{}};return{init:i,state:l,setupLights:o,setupLightsView:c,pushLight:r,pushShadow:s}}function iy(n){let e=new WeakMap;function t(i,r=0){const s=e.get(i);let o;return s===void 0?(o=new gh(n),e.set(i,[o])):r>=s.length?(o=new gh(n),s.push(o)):o=s[r],o}function a(){e=new WeakMap}return{get:t,dispose:a}}class ry extends Vn{static get type(){return"MeshDepthMaterial"}constructor(e){super(),this.isMeshDepthMaterial=!0,this.depthPacking=Ou,this.map=null,this.alphaMap=null,this.displacementMap=null,this.displacementScale=1,this.displacementBias=0,this.wireframe=!1,this.wireframeLinewidth=1,this.setValues(e)}copy(e){return super.copy(e),this.depthPacking=e.depthPacking,this.map=e.map,this.alphaMap=e.alphaMap,this.displacementMap=e.displacementMap,this.displacementScale=e.displacementScale,this.displacementBias=e.displacementBias,this.wireframe=e.wireframe,this.wireframeLinewidth=e.wireframeLinewidth,this}}class sy extends Vn{static get type(){return"MeshDistanceMaterial"}constructor(e){super(),this.isMeshDistanceMaterial=!0,this.map=null,this.alphaMap=null,this.displacementMap=null,this.displacementScale=1,this.displacementBias=0,this.setValues(e)}copy(e){return super.copy(e),this.map=e.map,this.alphaMap=e.alphaMap,this.displacementMap=e.displacementMap,this.displacementScale=e.displacementScale,this.displacementBias=e.displacementBias,this}}const oy=`void main() {
	gl_Position = vec4( position, 1.0 );
}`,cy=`uniform sampler2D shadow_pass;
uniform vec2 resolution;
uniform float radius;
#include <packing>
void main() {
	const float samples = float( VSM_SAMPLES );
	float mean = 0.0;
	float squared_mean = 0.0;
	float uvStride = samples <= 1.0 ? 0.0 : 2.0 / ( samples - 1.0 );
	float uvStart = samples <= 1.0 ? 0.0 : - 1.0;
	for ( float i = 0.0; i < samples; i ++ ) {
		float uvOffset = uvStart + i * uvStride;
		#ifdef HORIZONTAL_PASS
			vec2 distribution = unpackRGBATo2Half( texture2D( shadow_pass, ( gl_FragCoord.xy + vec2( uvOffset, 0.0 ) * radius ) / resolution ) );
			mean += distribution.x;
			squared_mean += distribution.y * distribution.y + distribution.x * distribution.x;
		#else
			float depth = unpackRGBAToDepth( texture2D( shadow_pass, ( gl_FragCoord.xy + vec2( 0.0, uvOffset ) * radius ) / resolution ) );
			mean += depth;
			squared_mean += depth * depth;
		#endif
	}
	mean = mean / samples;
	squared_mean = squared_mean / samples;
	float std_dev = sqrt( squared_mean - mean * mean );
	gl_FragColor = pack2HalfToRGBA( vec2( mean, std_dev ) );
}`;function hy(n,e,t){let a=new rd;const i=new De,r=new De,s=new ot,o=new ry({depthPacking:zu}),c=new sy,l={},h=t.maxTextureSize,d={[Ma]:Ut,[Ut]:Ma,[Kt]:Kt},f=new Jt({defines:{VSM_SAMPLES:8},uniforms:{shadow_pass:{value:null},resolution:{value:new De},radius:{value:4}},vertexShader:oy,fragmentShader:cy}),b=f.clone();b.defines.HORIZONTAL_PASS=1;const p=new pt;p.setAttribute("position",new Be(new Float32Array([-1,-1,.5,3,-1,.5,-1,3,.5]),3));const g=new Nt(p,f),m=this;this.enabled=!1,this.autoUpdate=!0,this.needsUpdate=!1,this.type=Pl;let u=this.type;this.render=function(_,A,k){if(m.enabled===!1||m.autoUpdate===!1&&m.needsUpdate===!1||_.length===0)return;const w=n.getRenderTarget(),M=n.getActiveCubeFace(),R=n.getActiveMipmapLevel(),U=n.state;U.setBlending(Ga),U.buffers.color.setClear(1,1,1,1),U.buffers.depth.setTest(!0),U.setScissorTest(!1);const P=u!==pa&&this.type===pa,D=u===pa&&this.type!==pa;for(let V=0,B=_.length;V<B;V++){const G=_[V],z=G.shadow;if(z===void 0){console.warn("THREE.WebGLShadowMap:",G,"has no shadow.");continue}if(z.autoUpdate===!1&&z.needsUpdate===!1)continue;i.copy(z.mapSize);const Y=z.getFrameExtents();if(i.multiply(Y),r.copy(z.mapSize),(i.x>h||i.y>h)&&(i.x>h&&(r.x=Math.floor(h/Y.x),i.x=r.x*Y.x,z.mapSize.x=r.x),i.y>h&&(r.y=Math.floor(h/Y.y),i.y=r.y*Y.y,z.mapSize.y=r.y)),z.map===null||P===!0||D===!0){const ie=this.type!==pa?{minFilter:dt,magFilter:dt}:{};z.map!==null&&z.map.dispose(),z.map=new Sa(i.x,i.y,ie),z.map.texture.name=G.name+".shadowMap",z.camera.updateProjectionMatrix()}n.setRenderTarget(z.map),n.clear();const te=z.getViewportCount();for(let ie=0;ie<te;ie++){const pe=z.getViewport(ie);s.set(r.x*pe.x,r.y*pe.y,r.x*pe.z,r.y*pe.w),U.viewport(s),z.updateMatrices(G,ie),a=z.getFrustum(),v(A,k,z.camera,G,this.type)}z.isPointLightShadow!==!0&&this.type===pa&&y(z,k),z.needsUpdate=!1}u=this.type,m.needsUpdate=!1,n.setRenderTarget(w,M,R)};function y(_,A){const k=e.update(g);f.defines.VSM_SAMPLES!==_.blurSamples&&(f.defines.VSM_SAMPLES=_.blurSamples,b.defines.VSM_SAMPLES=_.blurSamples,f.needsUpdate=!0,b.needsUpdate=!0),_.mapPass===null&&(_.mapPass=new Sa(i.x,i.y)),f.uniforms.shadow_pass.value=_.map.texture,f.uniforms.resolution.value=_.mapSize,f.uniforms.radius.value=_.radius,n.setRenderTarget(_.mapPass),n.clear(),n.renderBufferDirect(A,null,k,f,g,null),b.uniforms.shadow_pass.value=_.mapPass.texture,b.uniforms.resolution.value=_.mapSize,b.uniforms.radius.value=_.radius,n.setRenderTarget(_.map),n.clear(),n.renderBufferDirect(A,null,k,b,g,null)}function x(_,A,k,w){let M=null;const R=k.isPointLight===!0?_.customDistanceMaterial:_.customDepthMaterial;if(R!==void 0)M=R;else if(M=k.isPointLight===!0?c:o,n.localClippingEnabled&&A.clipShadows===!0&&Array.isArray(A.clippingPlanes)&&A.clippingPlanes.length!==0||A.displacementMap&&A.displacementScale!==0||A.alphaMap&&A.alphaTest>0||A.map&&A.alphaTest>0){const U=M.uuid,P=A.uuid;let D=l[U];D===void 0&&(D={},l[U]=D);let V=D[P];V===void 0&&(V=M.clone(),D[P]=V,A.addEventListener("dispose",E)),M=V}if(M.visible=A.visible,M.wireframe=A.wireframe,w===pa?M.side=A.shadowSide!==null?A.shadowSide:A.side:M.side=A.shadowSide!==null?A.shadowSide:d[A.side],M.alphaMap=A.alphaMap,M.alphaTest=A.alphaTest,M.map=A.map,M.clipShadows=A.clipShadows,M.clippingPlanes=A.clippingPlanes,M.clipIntersection=A.clipIntersection,M.displacementMap=A.displacementMap,M.displacementScale=A.displacementScale,M.displacementBias=A.displacementBias,M.wireframeLinewidth=A.wireframeLinewidth,M.linewidth=A.linewidth,k.isPointLight===!0&&M.isMeshDistanceMaterial===!0){const U=n.properties.get(M);U.light=k}return M}function v(_,A,k,w,M){if(_.visible===!1)return;if(_.layers.test(A.layers)&&(_.isMesh||_.isLine||_.isPoints)&&(_.castShadow||_.receiveShadow&&M===pa)&&(!_.frustumCulled||a.intersectsObject(_))){_.modelViewMatrix.multiplyMatrices(k.matrixWorldInverse,_.matrixWorld);const P=e.update(_),D=_.material;if(Array.isArray(D)){const V=P.groups;for(let B=0,G=V.length;B<G;B++){const z=V[B],Y=D[z.materialIndex];if(Y&&Y.visible){const te=x(_,Y,w,M);_.onBeforeShadow(n,_,A,k,P,te,z),n.renderBufferDirect(k,null,P,te,_,z),_.onAfterShadow(n,_,A,k,P,te,z)}}}else if(D.visible){const V=x(_,D,w,M);_.onBeforeShadow(n,_,A,k,P,V,null),n.renderBufferDirect(k,null,P,V,_,null),_.onAfterShadow(n,_,A,k,P,V,null)}}const U=_.children;for(let P=0,D=U.length;P<D;P++)v(U[P],A,k,w,M)}function E(_){_.target.removeEventListener("dispose",E);for(const k in l){const w=l[k],M=_.target.uuid;M in w&&(w[M].dispose(),delete w[M])}}}const ly={[Ds]:Ns,[Us]:js,[Fs]:Os,[Un]:Ls,[Ns]:Ds,[js]:Us,[Os]:Fs,[Ls]:Un};function dy(n,e){function t(){let N=!1;const he=new ot;let K=null;const $=new ot(0,0,0,0);return{setMask:function(fe){K!==fe&&!N&&(n.colorMask(fe,fe,fe,fe),K=fe)},setLocked:function(fe){N=fe},setClear:function(fe,le,Ne,ct,yt){yt===!0&&(fe*=ct,le*=ct,Ne*=ct),he.set(fe,le,Ne,ct),$.equals(he)===!1&&(n.clearColor(fe,le,Ne,ct),$.copy(he))},reset:function(){N=!1,K=null,$.set(-1,0,0,0)}}}function a(){let N=!1,he=!1,K=null,$=null,fe=null;return{setReversed:function(le){if(he!==le){const Ne=e.get("EXT_clip_control");he?Ne.clipControlEXT(Ne.LOWER_LEFT_EXT,Ne.ZERO_TO_ONE_EXT):Ne.clipControlEXT(Ne.LOWER_LEFT_EXT,Ne.NEGATIVE_ONE_TO_ONE_EXT);const ct=fe;fe=null,this.setClear(ct)}he=le},getReversed:function(){return he},setTest:function(le){le?re(n.DEPTH_TEST):ge(n.DEPTH_TEST)},setMask:function(le){K!==le&&!N&&(n.depthMask(le),K=le)},setFunc:function(le){if(he&&(le=ly[le]),$!==le){switch(le){case Ds:n.depthFunc(n.NEVER);break;case Ns:n.depthFunc(n.ALWAYS);break;case Us:n.depthFunc(n.LESS);break;case Un:n.depthFunc(n.LEQUAL);break;case Fs:n.depthFunc(n.EQUAL);break;case Ls:n.depthFunc(n.GEQUAL);break;case js:n.depthFunc(n.GREATER);break;case Os:n.depthFunc(n.NOTEQUAL);break;default:n.depthFunc(n.LEQUAL)}$=le}},setLocked:function(le){N=le},setClear:function(le){fe!==le&&(he&&(le=1-le),n.clearDepth(le),fe=le)},reset:function(){N=!1,K=null,$=null,fe=null,he=!1}}}function i(){let N=!1,he=null,K=null,$=null,fe=null,le=null,Ne=null,ct=null,yt=null;return{setTest:function(Qe){N||(Qe?re(n.STENCIL_TEST):ge(n.STENCIL_TEST))},setMask:function(Qe){he!==Qe&&!N&&(n.stencilMask(Qe),he=Qe)},setFunc:function(Qe,Yt,ca){(K!==Qe||$!==Yt||fe!==ca)&&(n.stencilFunc(Qe,Yt,ca),K=Qe,$=Yt,fe=ca)},setOp:function(Qe,Yt,ca){(le!==Qe||Ne!==Yt||ct!==ca)&&(n.stencilOp(Qe,Yt,ca),le=Qe,Ne=Yt,ct=ca)},setLocked:function(Qe){N=Qe},setClear:function(Qe){yt!==Qe&&(n.clearStencil(Qe),yt=Qe)},reset:function(){N=!1,he=null,K=null,$=null,fe=null,le=null,Ne=null,ct=null,yt=null}}}const r=new t,s=new a,o=new i,c=new WeakMap,l=new WeakMap;let h={},d={},f=new WeakMap,b=[],p=null,g=!1,m=null,u=null,y=null,x=null,v=null,E=null,_=null,A=new Ve(0,0,0),k=0,w=!1,M=null,R=null,U=null,P=null,D=null;const V=n.getParameter(n.MAX_COMBINED_TEXTURE_IMAGE_UNITS);let B=!1,G=0;const z=n.getParameter(n.VERSION);z.indexOf("WebGL")!==-1?(G=parseFloat(/^WebGL (\d)/.exec(z)[1]),B=G>=1):z.indexOf("OpenGL ES")!==-1&&(G=parseFloat(/^OpenGL ES (\d)/.exec(z)[1]),B=G>=2);let Y=null,te={};const ie=n.getParameter(n.SCISSOR_BOX),pe=n.getParameter(n.VIEWPORT),Te=new ot().fromArray(ie),W=new ot().fromArray(pe);function J(N,he,K,$){const fe=new Uint8Array(4),le=n.createTexture();n.bindTexture(N,le),n.texParameteri(N,n.TEXTURE_MIN_FILTER,n.NEAREST),n.texParameteri(N,n.TEXTURE_MAG_FILTER,n.NEAREST);for(let Ne=0;Ne<K;Ne++)N===n.TEXTURE_3D||N===n.TEXTURE_2D_ARRAY?n.texImage3D(he,0,n.RGBA,1,1,$,0,n.RGBA,n.UNSIGNED_BYTE,fe):n.texImage2D(he+Ne,0,n.RGBA,1,1,0,n.RGBA,n.UNSIGNED_BYTE,fe);return le}const se={};se[n.TEXTURE_2D]=J(n.TEXTURE_2D,n.TEXTURE_2D,1),se[n.TEXTURE_CUBE_MAP]=J(n.TEXTURE_CUBE_MAP,n.TEXTURE_CUBE_MAP_POSITIVE_X,6),se[n.TEXTURE_2D_ARRAY]=J(n.TEXTURE_2D_ARRAY,n.TEXTURE_2D_ARRAY,1,1),se[n.TEXTURE_3D]=J(n.TEXTURE_3D,n.TEXTURE_3D,1,1),r.setClear(0,0,0,1),s.setClear(1),o.setClear(0),re(n.DEPTH_TEST),s.setFunc(Un),je(!1),Oe(wc),re(n.CULL_FACE),F(Ga);function re(N){h[N]!==!0&&(n.enable(N),h[N]=!0)}function ge(N){h[N]!==!1&&(n.disable(N),h[N]=!1)}function Ae(N,he){return d[N]!==he?(n.bindFramebuffer(N,he),d[N]=he,N===n.DRAW_FRAMEBUFFER&&(d[n.FRAMEBUFFER]=he),N===n.FRAMEBUFFER&&(d[n.DRAW_FRAMEBUFFER]=he),!0):!1}function Re(N,he){let K=b,$=!1;if(N){K=f.get(he),K===void 0&&(K=[],f.set(he,K));const fe=N.textures;if(K.length!==fe.length||K[0]!==n.COLOR_ATTACHMENT0){for(let le=0,Ne=fe.length;le<Ne;le++)K[le]=n.COLOR_ATTACHMENT0+le;K.length=fe.length,$=!0}}else K[0]!==n.BACK&&(K[0]=n.BACK,$=!0);$&&n.drawBuffers(K)}function We(N){return p!==N?(n.useProgram(N),p=N,!0):!1}const Ie={[en]:n.FUNC_ADD,[uu]:n.FUNC_SUBTRACT,[bu]:n.FUNC_REVERSE_SUBTRACT};Ie[mu]=n.MIN,Ie[pu]=n.MAX;const Ke={[gu]:n.ZERO,[vu]:n.ONE,[yu]:n.SRC_COLOR,[Is]:n.SRC_ALPHA,[Su]:n.SRC_ALPHA_SATURATE,[_u]:n.DST_COLOR,[wu]:n.DST_ALPHA,[xu]:n.ONE_MINUS_SRC_COLOR,[Ps]:n.ONE_MINUS_SRC_ALPHA,[Eu]:n.ONE_MINUS_DST_COLOR,[Mu]:n.ONE_MINUS_DST_ALPHA,[Au]:n.CONSTANT_COLOR,[Tu]:n.ONE_MINUS_CONSTANT_COLOR,[ku]:n.CONSTANT_ALPHA,[Ru]:n.ONE_MINUS_CONSTANT_ALPHA};function F(N,he,K,$,fe,le,Ne,ct,yt,Qe){if(N===Ga){g===!0&&(ge(n.BLEND),g=!1);return}if(g===!1&&(re(n.BLEND),g=!0),N!==fu){if(N!==m||Qe!==w){if((u!==en||v!==en)&&(n.blendEquation(n.FUNC_ADD),u=en,v=en),Qe)switch(N){case Pn:n.blendFuncSeparate(n.ONE,n.ONE_MINUS_SRC_ALPHA,n.ONE,n.ONE_MINUS_SRC_ALPHA);break;case Mc:n.blendFunc(n.ONE,n.ONE);break;case _c:n.blendFuncSeparate(n.ZERO,n.ONE_MINUS_SRC_COLOR,n.ZERO,n.ONE);break;case Ec:n.blendFuncSeparate(n.ZERO,n.SRC_COLOR,n.ZERO,n.SRC_ALPHA);break;default:console.error("THREE.WebGLState: Invalid blending: ",N);break}else switch(N){case Pn:n.blendFuncSeparate(n.SRC_ALPHA,n.ONE_MINUS_SRC_ALPHA,n.ONE,n.ONE_MINUS_SRC_ALPHA);break;case Mc:n.blendFunc(n.SRC_ALPHA,n.ONE);break;case _c:n.blendFuncSeparate(n.ZERO,n.ONE_MINUS_SRC_COLOR,n.ZERO,n.ONE);break;case Ec:n.blendFunc(n.ZERO,n.SRC_COLOR);break;default:console.error("THREE.WebGLState: Invalid blending: ",N);break}y=null,x=null,E=null,_=null,A.set(0,0,0),k=0,m=N,w=Qe}return}fe=fe||he,le=le||K,Ne=Ne||$,(he!==u||fe!==v)&&(n.blendEquationSeparate(Ie[he],Ie[fe]),u=he,v=fe),(K!==y||$!==x||le!==E||Ne!==_)&&(n.blendFuncSeparate(Ke[K],Ke[$],Ke[le],Ke[Ne]),y=K,x=$,E=le,_=Ne),(ct.equals(A)===!1||yt!==k)&&(n.blendColor(ct.r,ct.g,ct.b,yt),A.copy(ct),k=yt),m=N,w=!1}function vt(N,he){N.side===Kt?ge(n.CULL_FACE):re(n.CULL_FACE);let K=N.side===Ut;he&&(K=!K),je(K),N.blending===Pn&&N.transparent===!1?F(Ga):F(N.blending,N.blendEquation,N.blendSrc,N.blendDst,N.blendEquationAlpha,N.blendSrcAlpha,N.blendDstAlpha,N.blendColor,N.blendAlpha,N.premultipliedAlpha),s.setFunc(N.depthFunc),s.setTest(N.depthTest),s.setMask(N.depthWrite),r.setMask(N.colorWrite);const $=N.stencilWrite;o.setTest($),$&&(o.setMask(N.stencilWriteMask),o.setFunc(N.stencilFunc,N.stencilRef,N.stencilFuncMask),o.setOp(N.stencilFail,N.stencilZFail,N.stencilZPass)),Ze(N.polygonOffset,N.polygonOffsetFactor,N.polygonOffsetUnits),N.alphaToCoverage===!0?re(n.SAMPLE_ALPHA_TO_COVERAGE):ge(n.SAMPLE_ALPHA_TO_COVERAGE)}function je(N){M!==N&&(N?n.frontFace(n.CW):n.frontFace(n.CCW),M=N)}function Oe(N){N!==hu?(re(n.CULL_FACE),N!==R&&(N===wc?n.cullFace(n.BACK):N===lu?n.cullFace(n.FRONT):n.cullFace(n.FRONT_AND_BACK))):ge(n.CULL_FACE),R=N}function Ee(N){N!==U&&(B&&n.lineWidth(N),U=N)}function Ze(N,he,K){N?(re(n.POLYGON_OFFSET_FILL),(P!==he||D!==K)&&(n.polygonOffset(he,K),P=he,D=K)):ge(n.POLYGON_OFFSET_FILL)}function _e(N){N?re(n.SCISSOR_TEST):ge(n.SCISSOR_TEST)}function C(N){N===void 0&&(N=n.TEXTURE0+V-1),Y!==N&&(n.activeTexture(N),Y=N)}function S(N,he,K){K===void 0&&(Y===null?K=n.TEXTURE0+V-1:K=Y);let $=te[K];$===void 0&&($={type:void 0,texture:void 0},te[K]=$),($.type!==N||$.texture!==he)&&(Y!==K&&(n.activeTexture(K),Y=K),n.bindTexture(N,he||se[N]),$.type=N,$.texture=he)}function H(){const N=te[Y];N!==void 0&&N.type!==void 0&&(n.bindTexture(N.type,null),N.type=void 0,N.texture=void 0)}function Q(){try{n.compressedTexImage2D.apply(n,arguments)}catch(N){console.error("THREE.WebGLState:",N)}}function ee(){try{n.compressedTexImage3D.apply(n,arguments)}catch(N){console.error("THREE.WebGLState:",N)}}function Z(){try{n.texSubImage2D.apply(n,arguments)}catch(N){console.error("THREE.WebGLState:",N)}}function ve(){try{n.texSubImage3D.apply(n,arguments)}catch(N){console.error("THREE.WebGLState:",N)}}function ce(){try{n.compressedTexSubImage2D.apply(n,arguments)}catch(N){console.error("THREE.WebGLState:",N)}}function be(){try{n.compressedTexSubImage3D.apply(n,arguments)}catch(N){console.error("THREE.WebGLState:",N)}}function Ge(){try{n.texStorage2D.apply(n,arguments)}catch(N){console.error("THREE.WebGLState:",N)}}function ae(){try{n.texStorage3D.apply(n,arguments)}catch(N){console.error("THREE.WebGLState:",N)}}function me(){try{n.texImage2D.apply(n,arguments)}catch(N){console.error("THREE.WebGLState:",N)}}function Se(){try{n.texImage3D.apply(n,arguments)}catch(N){console.error("THREE.WebGLState:",N)}}function ke(N){Te.equals(N)===!1&&(n.scissor(N.x,N.y,N.z,N.w),Te.copy(N))}function ue(N){W.equals(N)===!1&&(n.viewport(N.x,N.y,N.z,N.w),W.copy(N))}function He(N,he){let K=l.get(he);K===void 0&&(K=new WeakMap,l.set(he,K));let $=K.get(N);$===void 0&&($=n.getUniformBlockIndex(he,N.name),K.set(N,$))}function Fe(N,he){const $=l.get(he).get(N);c.get(he)!==$&&(n.uniformBlockBinding(he,$,N.__bindingPointIndex),c.set(he,$))}function at(){n.disable(n.BLEND),n.disable(n.CULL_FACE),n.disable(n.DEPTH_TEST),n.disable(n.POLYGON_OFFSET_FILL),n.disable(n.SCISSOR_TEST),n.disable(n.STENCIL_TEST),n.disable(n.SAMPLE_ALPHA_TO_COVERAGE),n.blendEquation(n.FUNC_ADD),n.blendFunc(n.ONE,n.ZERO),n.blendFuncSeparate(n.ONE,n.ZERO,n.ONE,n.ZERO),n.blendColor(0,0,0,0),n.colorMask(!0,!0,!0,!0),n.clearColor(0,0,0,0),n.depthMask(!0),n.depthFunc(n.LESS),s.setReversed(!1),n.clearDepth(1),n.stencilMask(4294967295),n.stencilFunc(n.ALWAYS,0,4294967295),n.stencilOp(n.KEEP,n.KEEP,n.KEEP),n.clearStencil(0),n.cullFace(n.BACK),n.frontFace(n.CCW),n.polygonOffset(0,0),n.activeTexture(n.TEXTURE0),n.bindFramebuffer(n.FRAMEBUFFER,null),n.bindFramebuffer(n.DRAW_FRAMEBUFFER,null),n.bindFramebuffer(n.READ_FRAMEBUFFER,null),n.useProgram(null),n.lineWidth(1),n.scissor(0,0,n.canvas.width,n.canvas.height),n.viewport(0,0,n.canvas.width,n.canvas.height),h={},Y=null,te={},d={},f=new WeakMap,b=[],p=null,g=!1,m=null,u=null,y=null,x=null,v=null,E=null,_=null,A=new Ve(0,0,0),k=0,w=!1,M=null,R=null,U=null,P=null,D=null,Te.set(0,0,n.canvas.width,n.canvas.height),W.set(0,0,n.canvas.width,n.canvas.height),r.reset(),s.reset(),o.reset()}return{buffers:{color:r,depth:s,stencil:o},enable:re,disable:ge,bindFramebuffer:Ae,drawBuffers:Re,useProgram:We,setBlending:F,setMaterial:vt,setFlipSided:je,setCullFace:Oe,setLineWidth:Ee,setPolygonOffset:Ze,setScissorTest:_e,activeTexture:C,bindTexture:S,unbindTexture:H,compressedTexImage2D:Q,compressedTexImage3D:ee,texImage2D:me,texImage3D:Se,updateUBOMapping:He,uniformBlockBinding:Fe,texStorage2D:Ge,texStorage3D:ae,texSubImage2D:Z,texSubImage3D:ve,compressedTexSubImage2D:ce,compressedTexSubImage3D:be,scissor:ke,viewport:ue,reset:at}}function vh(n,e,t,a){const i=fy(a);switch(t){case Ol:return n*e;case Bl:return n*e;case Gl:return n*e*2;case Hl:return n*e/i.components*i.byteLength;case Fo:return n*e/i.components*i.byteLength;case Vl:return n*e*2/i.components*i.byteLength;case Lo:return n*e*2/i.components*i.byteLength;case zl:return n*e*3/i.components*i.byteLength;case Rt:return n*e*4/i.components*i.byteLength;case jo:return n*e*4/i.components*i.byteLength;case sr:case or:return Math.floor((n+3)/4)*Math.floor((e+3)/4)*8;case cr:case hr:return Math.floor((n+3)/4)*Math.floor((e+3)/4)*16;case Vs:case qs:return Math.max(n,16)*Math.max(e,8)/4;case Hs:case Ws:return Math.max(n,8)*Math.max(e,8)/2;case Xs:case Ks:return Math.floor((n+3)/4)*Math.floor((e+3)/4)*8;case Js:return Math.floor((n+3)/4)*Math.floor((e+3)/4)*16;case Ys:return Math.floor((n+3)/4)*Math.floor((e+3)/4)*16;case Zs:return Math.floor((n+4)/5)*Math.floor((e+3)/4)*16;case Qs:return Math.floor((n+4)/5)*Math.floor((e+4)/5)*16;case $s:return Math.floor((n+5)/6)*Math.floor((e+4)/5)*16;case eo:return Math.floor((n+5)/6)*Math.floor((e+5)/6)*16;case to:return Math.floor((n+7)/8)*Math.floor((e+4)/5)*16;case ao:return Math.floor((n+7)/8)*Math.floor((e+5)/6)*16;case no:return Math.floor((n+7)/8)*Math.floor((e+7)/8)*16;case io:return Math.floor((n+9)/10)*Math.floor((e+4)/5)*16;case ro:return Math.floor((n+9)/10)*Math.floor((e+5)/6)*16;case so:return Math.floor((n+9)/10)*Math.floor((e+7)/8)*16;case oo:return Math.floor((n+9)/10)*Math.floor((e+9)/10)*16;case co:return Math.floor((n+11)/12)*Math.floor((e+9)/10)*16;case ho:return Math.floor((n+11)/12)*Math.floor((e+11)/12)*16;case lr:case lo:case fo:return Math.ceil(n/4)*Math.ceil(e/4)*16;case Wl:case uo:return Math.ceil(n/4)*Math.ceil(e/4)*8;case bo:case mo:return Math.ceil(n/4)*Math.ceil(e/4)*16}throw new Error(`Unable to determine texture byte length for ${t} format.`)}function fy(n){switch(n){case _a:case Fl:return{byteLength:1,components:1};case vi:case Ll:case Si:return{byteLength:2,components:1};case No:case Uo:return{byteLength:2,components:4};case sn:case Do:case zt:return{byteLength:4,components:1};case jl:return{byteLength:4,components:3}}throw new Error(`Unknown texture type ${n}.`)}function uy(n,e,t,a,i,r,s){const o=e.has("WEBGL_multisampled_render_to_texture")?e.get("WEBGL_multisampled_render_to_texture"):null,c=typeof navigator>"u"?!1:/OculusBrowser/g.test(navigator.userAgent),l=new De,h=new WeakMap;let d;const f=new WeakMap;let b=!1;try{b=typeof OffscreenCanvas<"u"&&new OffscreenCanvas(1,1).getContext("2d")!==null}catch{}function p(C,S){return b?new OffscreenCanvas(C,S):yr("canvas")}function g(C,S,H){let Q=1;const ee=_e(C);if((ee.width>H||ee.height>H)&&(Q=H/Math.max(ee.width,ee.height)),Q<1)if(typeof HTMLImageElement<"u"&&C instanceof HTMLImageElement||typeof HTMLCanvasElement<"u"&&C instanceof HTMLCanvasElement||typeof ImageBitmap<"u"&&C instanceof ImageBitmap||typeof VideoFrame<"u"&&C instanceof VideoFrame){const Z=Math.floor(Q*ee.width),ve=Math.floor(Q*ee.height);d===void 0&&(d=p(Z,ve));const ce=S?p(Z,ve):d;return ce.width=Z,ce.height=ve,ce.getContext("2d").drawImage(C,0,0,Z,ve),console.warn("THREE.WebGLRenderer: Texture has been resized from ("+ee.width+"x"+ee.height+") to ("+Z+"x"+ve+")."),ce}else return"data"in C&&console.warn("THREE.WebGLRenderer: Image in DataTexture is too big ("+ee.width+"x"+ee.height+")."),C;return C}function m(C){return C.generateMipmaps}function u(C){n.generateMipmap(C)}function y(C){return C.isWebGLCubeRenderTarget?n.TEXTURE_CUBE_MAP:C.isWebGL3DRenderTarget?n.TEXTURE_3D:C.isWebGLArrayRenderTarget||C.isCompressedArrayTexture?n.TEXTURE_2D_ARRAY:n.TEXTURE_2D}function x(C,S,H,Q,ee=!1){if(C!==null){if(n[C]!==void 0)return n[C];console.warn("THREE.WebGLRenderer: Attempt to use non-existing WebGL internal format '"+C+"'")}let Z=S;if(S===n.RED&&(H===n.FLOAT&&(Z=n.R32F),H===n.HALF_FLOAT&&(Z=n.R16F),H===n.UNSIGNED_BYTE&&(Z=n.R8)),S===n.RED_INTEGER&&(H===n.UNSIGNED_BYTE&&(Z=n.R8UI),H===n.UNSIGNED_SHORT&&(Z=n.R16UI),H===n.UNSIGNED_INT&&(Z=n.R32UI),H===n.BYTE&&(Z=n.R8I),H===n.SHORT&&(Z=n.R16I),H===n.INT&&(Z=n.R32I)),S===n.RG&&(H===n.FLOAT&&(Z=n.RG32F),H===n.HALF_FLOAT&&(Z=n.RG16F),H===n.UNSIGNED_BYTE&&(Z=n.RG8)),S===n.RG_INTEGER&&(H===n.UNSIGNED_BYTE&&(Z=n.RG8UI),H===n.UNSIGNED_SHORT&&(Z=n.RG16UI),H===n.UNSIGNED_INT&&(Z=n.RG32UI),H===n.BYTE&&(Z=n.RG8I),H===n.SHORT&&(Z=n.RG16I),H===n.INT&&(Z=n.RG32I)),S===n.RGB_INTEGER&&(H===n.UNSIGNED_BYTE&&(Z=n.RGB8UI),H===n.UNSIGNED_SHORT&&(Z=n.RGB16UI),H===n.UNSIGNED_INT&&(Z=n.RGB32UI),H===n.BYTE&&(Z=n.RGB8I),H===n.SHORT&&(Z=n.RGB16I),H===n.INT&&(Z=n.RGB32I)),S===n.RGBA_INTEGER&&(H===n.UNSIGNED_BYTE&&(Z=n.RGBA8UI),H===n.UNSIGNED_SHORT&&(Z=n.RGBA16UI),H===n.UNSIGNED_INT&&(Z=n.RGBA32UI),H===n.BYTE&&(Z=n.RGBA8I),H===n.SHORT&&(Z=n.RGBA16I),H===n.INT&&(Z=n.RGBA32I)),S===n.RGB&&H===n.UNSIGNED_INT_5_9_9_9_REV&&(Z=n.RGB9_E5),S===n.RGBA){const ve=ee?Rr:qe.getTransfer(Q);H===n.FLOAT&&(Z=n.RGBA32F),H===n.HALF_FLOAT&&(Z=n.RGBA16F),H===n.UNSIGNED_BYTE&&(Z=ve===et?n.SRGB8_ALPHA8:n.RGBA8),H===n.UNSIGNED_SHORT_4_4_4_4&&(Z=n.RGBA4),H===n.UNSIGNED_SHORT_5_5_5_1&&(Z=n.RGB5_A1)}return(Z===n.R16F||Z===n.R32F||Z===n.RG16F||Z===n.RG32F||Z===n.RGBA16F||Z===n.RGBA32F)&&e.get("EXT_color_buffer_float"),Z}function v(C,S){let H;return C?S===null||S===sn||S===jn?H=n.DEPTH24_STENCIL8:S===zt?H=n.DEPTH32F_STENCIL8:S===vi&&(H=n.DEPTH24_STENCIL8,console.warn("DepthTexture: 16 bit depth attachment is not supported with stencil. Using 24-bit attachment.")):S===null||S===sn||S===jn?H=n.DEPTH_COMPONENT24:S===zt?H=n.DEPTH_COMPONENT32F:S===vi&&(H=n.DEPTH_COMPONENT16),H}function E(C,S){return m(C)===!0||C.isFramebufferTexture&&C.minFilter!==dt&&C.minFilter!==na?Math.log2(Math.max(S.width,S.height))+1:C.mipmaps!==void 0&&C.mipmaps.length>0?C.mipmaps.length:C.isCompressedTexture&&Array.isArray(C.image)?S.mipmaps.length:1}function _(C){const S=C.target;S.removeEventListener("dispose",_),k(S),S.isVideoTexture&&h.delete(S)}function A(C){const S=C.target;S.removeEventListener("dispose",A),M(S)}function k(C){const S=a.get(C);if(S.__webglInit===void 0)return;const H=C.source,Q=f.get(H);if(Q){const ee=Q[S.__cacheKey];ee.usedTimes--,ee.usedTimes===0&&w(C),Object.keys(Q).length===0&&f.delete(H)}a.remove(C)}function w(C){const S=a.get(C);n.deleteTexture(S.__webglTexture);const H=C.source,Q=f.get(H);delete Q[S.__cacheKey],s.memory.textures--}function M(C){const S=a.get(C);if(C.depthTexture&&(C.depthTexture.dispose(),a.remove(C.depthTexture)),C.isWebGLCubeRenderTarget)for(let Q=0;Q<6;Q++){if(Array.isArray(S.__webglFramebuffer[Q]))for(let ee=0;ee<S.__webglFramebuffer[Q].length;ee++)n.deleteFramebuffer(S.__webglFramebuffer[Q][ee]);else n.deleteFramebuffer(S.__webglFramebuffer[Q]);S.__webglDepthbuffer&&n.deleteRenderbuffer(S.__webglDepthbuffer[Q])}else{if(Array.isArray(S.__webglFramebuffer))for(let Q=0;Q<S.__webglFramebuffer.length;Q++)n.deleteFramebuffer(S.__webglFramebuffer[Q]);else n.deleteFramebuffer(S.__webglFramebuffer);if(S.__webglDepthbuffer&&n.deleteRenderbuffer(S.__webglDepthbuffer),S.__webglMultisampledFramebuffer&&n.deleteFramebuffer(S.__webglMultisampledFramebuffer),S.__webglColorRenderbuffer)for(let Q=0;Q<S.__webglColorRenderbuffer.length;Q++)S.__webglColorRenderbuffer[Q]&&n.deleteRenderbuffer(S.__webglColorRenderbuffer[Q]);S.__webglDepthRenderbuffer&&n.deleteRenderbuffer(S.__webglDepthRenderbuffer)}const H=C.textures;for(let Q=0,ee=H.length;Q<ee;Q++){const Z=a.get(H[Q]);Z.__webglTexture&&(n.deleteTexture(Z.__webglTexture),s.memory.textures--),a.remove(H[Q])}a.remove(C)}let R=0;function U(){R=0}function P(){const C=R;return C>=i.maxTextures&&console.warn("THREE.WebGLTextures: Trying to use "+C+" texture units while this GPU supports only "+i.maxTextures),R+=1,C}function D(C){const S=[];return S.push(C.wrapS),S.push(C.wrapT),S.push(C.wrapR||0),S.push(C.magFilter),S.push(C.minFilter),S.push(C.anisotropy),S.push(C.internalFormat),S.push(C.format),S.push(C.type),S.push(C.generateMipmaps),S.push(C.premultiplyAlpha),S.push(C.flipY),S.push(C.unpackAlignment),S.push(C.colorSpace),S.join()}function V(C,S){const H=a.get(C);if(C.isVideoTexture&&Ee(C),C.isRenderTargetTexture===!1&&C.version>0&&H.__version!==C.version){const Q=C.image;if(Q===null)console.warn("THREE.WebGLRenderer: Texture marked for update but no image data found.");else if(Q.complete===!1)console.warn("THREE.WebGLRenderer: Texture marked for update but image is incomplete");else{W(H,C,S);return}}t.bindTexture(n.TEXTURE_2D,H.__webglTexture,n.TEXTURE0+S)}function B(C,S){const H=a.get(C);if(C.version>0&&H.__version!==C.version){W(H,C,S);return}t.bindTexture(n.TEXTURE_2D_ARRAY,H.__webglTexture,n.TEXTURE0+S)}function G(C,S){const H=a.get(C);if(C.version>0&&H.__version!==C.version){W(H,C,S);return}t.bindTexture(n.TEXTURE_3D,H.__webglTexture,n.TEXTURE0+S)}function z(C,S){const H=a.get(C);if(C.version>0&&H.__version!==C.version){J(H,C,S);return}t.bindTexture(n.TEXTURE_CUBE_MAP,H.__webglTexture,n.TEXTURE0+S)}const Y={[pr]:n.REPEAT,[za]:n.CLAMP_TO_EDGE,[gr]:n.MIRRORED_REPEAT},te={[dt]:n.NEAREST,[Ul]:n.NEAREST_MIPMAP_NEAREST,[ci]:n.NEAREST_MIPMAP_LINEAR,[na]:n.LINEAR,[rr]:n.LINEAR_MIPMAP_NEAREST,[Ba]:n.LINEAR_MIPMAP_LINEAR},ie={[Hu]:n.NEVER,[Ju]:n.ALWAYS,[Vu]:n.LESS,[ql]:n.LEQUAL,[Wu]:n.EQUAL,[Ku]:n.GEQUAL,[qu]:n.GREATER,[Xu]:n.NOTEQUAL};function pe(C,S){if(S.type===zt&&e.has("OES_texture_float_linear")===!1&&(S.magFilter===na||S.magFilter===rr||S.magFilter===ci||S.magFilter===Ba||S.minFilter===na||S.minFilter===rr||S.minFilter===ci||S.minFilter===Ba)&&console.warn("THREE.WebGLRenderer: Unable to use linear filtering with floating point textures. OES_texture_float_linear not supported on this device."),n.texParameteri(C,n.TEXTURE_WRAP_S,Y[S.wrapS]),n.texParameteri(C,n.TEXTURE_WRAP_T,Y[S.wrapT]),(C===n.TEXTURE_3D||C===n.TEXTURE_2D_ARRAY)&&n.texParameteri(C,n.TEXTURE_WRAP_R,Y[S.wrapR]),n.texParameteri(C,n.TEXTURE_MAG_FILTER,te[S.magFilter]),n.texParameteri(C,n.TEXTURE_MIN_FILTER,te[S.minFilter]),S.compareFunction&&(n.texParameteri(C,n.TEXTURE_COMPARE_MODE,n.COMPARE_REF_TO_TEXTURE),n.texParameteri(C,n.TEXTURE_COMPARE_FUNC,ie[S.compareFunction])),e.has("EXT_texture_filter_anisotropic")===!0){if(S.magFilter===dt||S.minFilter!==ci&&S.minFilter!==Ba||S.type===zt&&e.has("OES_texture_float_linear")===!1)return;if(S.anisotropy>1||a.get(S).__currentAnisotropy){const H=e.get("EXT_texture_filter_anisotropic");n.texParameterf(C,H.TEXTURE_MAX_ANISOTROPY_EXT,Math.min(S.anisotropy,i.getMaxAnisotropy())),a.get(S).__currentAnisotropy=S.anisotropy}}}function Te(C,S){let H=!1;C.__webglInit===void 0&&(C.__webglInit=!0,S.addEventListener("dispose",_));const Q=S.source;let ee=f.get(Q);ee===void 0&&(ee={},f.set(Q,ee));const Z=D(S);if(Z!==C.__cacheKey){ee[Z]===void 0&&(ee[Z]={texture:n.createTexture(),usedTimes:0},s.memory.textures++,H=!0),ee[Z].usedTimes++;const ve=ee[C.__cacheKey];ve!==void 0&&(ee[C.__cacheKey].usedTimes--,ve.usedTimes===0&&w(S)),C.__cacheKey=Z,C.__webglTexture=ee[Z].texture}return H}function W(C,S,H){let Q=n.TEXTURE_2D;(S.isDataArrayTexture||S.isCompressedArrayTexture)&&(Q=n.TEXTURE_2D_ARRAY),S.isData3DTexture&&(Q=n.TEXTURE_3D);const ee=Te(C,S),Z=S.source;t.bindTexture(Q,C.__webglTexture,n.TEXTURE0+H);const ve=a.get(Z);if(Z.version!==ve.__version||ee===!0){t.activeTexture(n.TEXTURE0+H);const ce=qe.getPrimaries(qe.workingColorSpace),be=S.colorSpace===ga?null:qe.getPrimaries(S.colorSpace),Ge=S.colorSpace===ga||ce===be?n.NONE:n.BROWSER_DEFAULT_WEBGL;n.pixelStorei(n.UNPACK_FLIP_Y_WEBGL,S.flipY),n.pixelStorei(n.UNPACK_PREMULTIPLY_ALPHA_WEBGL,S.premultiplyAlpha),n.pixelStorei(n.UNPACK_ALIGNMENT,S.unpackAlignment),n.pixelStorei(n.UNPACK_COLORSPACE_CONVERSION_WEBGL,Ge);let ae=g(S.image,!1,i.maxTextureSize);ae=Ze(S,ae);const me=r.convert(S.format,S.colorSpace),Se=r.convert(S.type);let ke=x(S.internalFormat,me,Se,S.colorSpace,S.isVideoTexture);pe(Q,S);let ue;const He=S.mipmaps,Fe=S.isVideoTexture!==!0,at=ve.__version===void 0||ee===!0,N=Z.dataReady,he=E(S,ae);if(S.isDepthTexture)ke=v(S.format===On,S.type),at&&(Fe?t.texStorage2D(n.TEXTURE_2D,1,ke,ae.width,ae.height):t.texImage2D(n.TEXTURE_2D,0,ke,ae.width,ae.height,0,me,Se,null));else if(S.isDataTexture)if(He.length>0){Fe&&at&&t.texStorage2D(n.TEXTURE_2D,he,ke,He[0].width,He[0].height);for(let K=0,$=He.length;K<$;K++)ue=He[K],Fe?N&&t.texSubImage2D(n.TEXTURE_2D,K,0,0,ue.width,ue.height,me,Se,ue.data):t.texImage2D(n.TEXTURE_2D,K,ke,ue.width,ue.height,0,me,Se,ue.data);S.generateMipmaps=!1}else Fe?(at&&t.texStorage2D(n.TEXTURE_2D,he,ke,ae.width,ae.height),N&&t.texSubImage2D(n.TEXTURE_2D,0,0,0,ae.width,ae.height,me,Se,ae.data)):t.texImage2D(n.TEXTURE_2D,0,ke,ae.width,ae.height,0,me,Se,ae.data);else if(S.isCompressedTexture)if(S.isCompressedArrayTexture){Fe&&at&&t.texStorage3D(n.TEXTURE_2D_ARRAY,he,ke,He[0].width,He[0].height,ae.depth);for(let K=0,$=He.length;K<$;K++)if(ue=He[K],S.format!==Rt)if(me!==null)if(Fe){if(N)if(S.layerUpdates.size>0){const fe=vh(ue.width,ue.height,S.format,S.type);for(const le of S.layerUpdates){const Ne=ue.data.subarray(le*fe/ue.data.BYTES_PER_ELEMENT,(le+1)*fe/ue.data.BYTES_PER_ELEMENT);t.compressedTexSubImage3D(n.TEXTURE_2D_ARRAY,K,0,0,le,ue.width,ue.height,1,me,Ne)}S.clearLayerUpdates()}else t.compressedTexSubImage3D(n.TEXTURE_2D_ARRAY,K,0,0,0,ue.width,ue.height,ae.depth,me,ue.data)}else t.compressedTexImage3D(n.TEXTURE_2D_ARRAY,K,ke,ue.width,ue.height,ae.depth,0,ue.data,0,0);else console.warn("THREE.WebGLRenderer: Attempt to load unsupported compressed texture format in .uploadTexture()");else Fe?N&&t.texSubImage3D(n.TEXTURE_2D_ARRAY,K,0,0,0,ue.width,ue.height,ae.depth,me,Se,ue.data):t.texImage3D(n.TEXTURE_2D_ARRAY,K,ke,ue.width,ue.height,ae.depth,0,me,Se,ue.data)}else{Fe&&at&&t.texStorage2D(n.TEXTURE_2D,he,ke,He[0].width,He[0].height);for(let K=0,$=He.length;K<$;K++)ue=He[K],S.format!==Rt?me!==null?Fe?N&&t.compressedTexSubImage2D(n.TEXTURE_2D,K,0,0,ue.width,ue.height,me,ue.data):t.compressedTexImage2D(n.TEXTURE_2D,K,ke,ue.width,ue.height,0,ue.data):console.warn("THREE.WebGLRenderer: Attempt to load unsupported compressed texture format in .uploadTexture()"):Fe?N&&t.texSubImage2D(n.TEXTURE_2D,K,0,0,ue.width,ue.height,me,Se,ue.data):t.texImage2D(n.TEXTURE_2D,K,ke,ue.width,ue.height,0,me,Se,ue.data)}else if(S.isDataArrayTexture)if(Fe){if(at&&t.texStorage3D(n.TEXTURE_2D_ARRAY,he,ke,ae.width,ae.height,ae.depth),N)if(S.layerUpdates.size>0){const K=vh(ae.width,ae.height,S.format,S.type);for(const $ of S.layerUpdates){const fe=ae.data.subarray($*K/ae.data.BYTES_PER_ELEMENT,($+1)*K/ae.data.BYTES_PER_ELEMENT);t.texSubImage3D(n.TEXTURE_2D_ARRAY,0,0,0,$,ae.width,ae.height,1,me,Se,fe)}S.clearLayerUpdates()}else t.texSubImage3D(n.TEXTURE_2D_ARRAY,0,0,0,0,ae.width,ae.height,ae.depth,me,Se,ae.data)}else t.texImage3D(n.TEXTURE_2D_ARRAY,0,ke,ae.width,ae.height,ae.depth,0,me,Se,ae.data);else if(S.isData3DTexture)Fe?(at&&t.texStorage3D(n.TEXTURE_3D,he,ke,ae.width,ae.height,ae.depth),N&&t.texSubImage3D(n.TEXTURE_3D,0,0,0,0,ae.width,ae.height,ae.depth,me,Se,ae.data)):t.texImage3D(n.TEXTURE_3D,0,ke,ae.width,ae.height,ae.depth,0,me,Se,ae.data);else if(S.isFramebufferTexture){if(at)if(Fe)t.texStorage2D(n.TEXTURE_2D,he,ke,ae.width,ae.height);else{let K=ae.width,$=ae.height;for(let fe=0;fe<he;fe++)t.texImage2D(n.TEXTURE_2D,fe,ke,K,$,0,me,Se,null),K>>=1,$>>=1}}else if(He.length>0){if(Fe&&at){const K=_e(He[0]);t.texStorage2D(n.TEXTURE_2D,he,ke,K.width,K.height)}for(let K=0,$=He.length;K<$;K++)ue=He[K],Fe?N&&t.texSubImage2D(n.TEXTURE_2D,K,0,0,me,Se,ue):t.texImage2D(n.TEXTURE_2D,K,ke,me,Se,ue);S.generateMipmaps=!1}else if(Fe){if(at){const K=_e(ae);t.texStorage2D(n.TEXTURE_2D,he,ke,K.width,K.height)}N&&t.texSubImage2D(n.TEXTURE_2D,0,0,0,me,Se,ae)}else t.texImage2D(n.TEXTURE_2D,0,ke,me,Se,ae);m(S)&&u(Q),ve.__version=Z.version,S.onUpdate&&S.onUpdate(S)}C.__version=S.version}function J(C,S,H){if(S.image.length!==6)return;const Q=Te(C,S),ee=S.source;t.bindTexture(n.TEXTURE_CUBE_MAP,C.__webglTexture,n.TEXTURE0+H);const Z=a.get(ee);if(ee.version!==Z.__version||Q===!0){t.activeTexture(n.TEXTURE0+H);const ve=qe.getPrimaries(qe.workingColorSpace),ce=S.colorSpace===ga?null:qe.getPrimaries(S.colorSpace),be=S.colorSpace===ga||ve===ce?n.NONE:n.BROWSER_DEFAULT_WEBGL;n.pixelStorei(n.UNPACK_FLIP_Y_WEBGL,S.flipY),n.pixelStorei(n.UNPACK_PREMULTIPLY_ALPHA_WEBGL,S.premultiplyAlpha),n.pixelStorei(n.UNPACK_ALIGNMENT,S.unpackAlignment),n.pixelStorei(n.UNPACK_COLORSPACE_CONVERSION_WEBGL,be);const Ge=S.isCompressedTexture||S.image[0].isCompressedTexture,ae=S.image[0]&&S.image[0].isDataTexture,me=[];for(let $=0;$<6;$++)!Ge&&!ae?me[$]=g(S.image[$],!0,i.maxCubemapSize):me[$]=ae?S.image[$].image:S.image[$],me[$]=Ze(S,me[$]);const Se=me[0],ke=r.convert(S.format,S.colorSpace),ue=r.convert(S.type),He=x(S.internalFormat,ke,ue,S.colorSpace),Fe=S.isVideoTexture!==!0,at=Z.__version===void 0||Q===!0,N=ee.dataReady;let he=E(S,Se);pe(n.TEXTURE_CUBE_MAP,S);let K;if(Ge){Fe&&at&&t.texStorage2D(n.TEXTURE_CUBE_MAP,he,He,Se.width,Se.height);for(let $=0;$<6;$++){K=me[$].mipmaps;for(let fe=0;fe<K.length;fe++){const le=K[fe];S.format!==Rt?ke!==null?Fe?N&&t.compressedTexSubImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+$,fe,0,0,le.width,le.height,ke,le.data):t.compressedTexImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+$,fe,He,le.width,le.height,0,le.data):console.warn("THREE.WebGLRenderer: Attempt to load unsupported compressed texture format in .setTextureCube()"):Fe?N&&t.texSubImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+$,fe,0,0,le.width,le.height,ke,ue,le.data):t.texImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+$,fe,He,le.width,le.height,0,ke,ue,le.data)}}}else{if(K=S.mipmaps,Fe&&at){K.length>0&&he++;const $=_e(me[0]);t.texStorage2D(n.TEXTURE_CUBE_MAP,he,He,$.width,$.height)}for(let $=0;$<6;$++)if(ae){Fe?N&&t.texSubImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+$,0,0,0,me[$].width,me[$].height,ke,ue,me[$].data):t.texImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+$,0,He,me[$].width,me[$].height,0,ke,ue,me[$].data);for(let fe=0;fe<K.length;fe++){const Ne=K[fe].image[$].image;Fe?N&&t.texSubImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+$,fe+1,0,0,Ne.width,Ne.height,ke,ue,Ne.data):t.texImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+$,fe+1,He,Ne.width,Ne.height,0,ke,ue,Ne.data)}}else{Fe?N&&t.texSubImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+$,0,0,0,ke,ue,me[$]):t.texImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+$,0,He,ke,ue,me[$]);for(let fe=0;fe<K.length;fe++){const le=K[fe];Fe?N&&t.texSubImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+$,fe+1,0,0,ke,ue,le.image[$]):t.texImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+$,fe+1,He,ke,ue,le.image[$])}}}m(S)&&u(n.TEXTURE_CUBE_MAP),Z.__version=ee.version,S.onUpdate&&S.onUpdate(S)}C.__version=S.version}function se(C,S,H,Q,ee,Z){const ve=r.convert(H.format,H.colorSpace),ce=r.convert(H.type),be=x(H.internalFormat,ve,ce,H.colorSpace),Ge=a.get(S),ae=a.get(H);if(ae.__renderTarget=S,!Ge.__hasExternalTextures){const me=Math.max(1,S.width>>Z),Se=Math.max(1,S.height>>Z);ee===n.TEXTURE_3D||ee===n.TEXTURE_2D_ARRAY?t.texImage3D(ee,Z,be,me,Se,S.depth,0,ve,ce,null):t.texImage2D(ee,Z,be,me,Se,0,ve,ce,null)}t.bindFramebuffer(n.FRAMEBUFFER,C),Oe(S)?o.framebufferTexture2DMultisampleEXT(n.FRAMEBUFFER,Q,ee,ae.__webglTexture,0,je(S)):(ee===n.TEXTURE_2D||ee>=n.TEXTURE_CUBE_MAP_POSITIVE_X&&ee<=n.TEXTURE_CUBE_MAP_NEGATIVE_Z)&&n.framebufferTexture2D(n.FRAMEBUFFER,Q,ee,ae.__webglTexture,Z),t.bindFramebuffer(n.FRAMEBUFFER,null)}function re(C,S,H){if(n.bindRenderbuffer(n.RENDERBUFFER,C),S.depthBuffer){const Q=S.depthTexture,ee=Q&&Q.isDepthTexture?Q.type:null,Z=v(S.stencilBuffer,ee),ve=S.stencilBuffer?n.DEPTH_STENCIL_ATTACHMENT:n.DEPTH_ATTACHMENT,ce=je(S);Oe(S)?o.renderbufferStorageMultisampleEXT(n.RENDERBUFFER,ce,Z,S.width,S.height):H?n.renderbufferStorageMultisample(n.RENDERBUFFER,ce,Z,S.width,S.height):n.renderbufferStorage(n.RENDERBUFFER,Z,S.width,S.height),n.framebufferRenderbuffer(n.FRAMEBUFFER,ve,n.RENDERBUFFER,C)}else{const Q=S.textures;for(let ee=0;ee<Q.length;ee++){const Z=Q[ee],ve=r.convert(Z.format,Z.colorSpace),ce=r.convert(Z.type),be=x(Z.internalFormat,ve,ce,Z.colorSpace),Ge=je(S);H&&Oe(S)===!1?n.renderbufferStorageMultisample(n.RENDERBUFFER,Ge,be,S.width,S.height):Oe(S)?o.renderbufferStorageMultisampleEXT(n.RENDERBUFFER,Ge,be,S.width,S.height):n.renderbufferStorage(n.RENDERBUFFER,be,S.width,S.height)}}n.bindRenderbuffer(n.RENDERBUFFER,null)}function ge(C,S){if(S&&S.isWebGLCubeRenderTarget)throw new Error("Depth Texture with cube render targets is not supported");if(t.bindFramebuffer(n.FRAMEBUFFER,C),!(S.depthTexture&&S.depthTexture.isDepthTexture))throw new Error("renderTarget.depthTexture must be an instance of THREE.DepthTexture");const Q=a.get(S.depthTexture);Q.__renderTarget=S,(!Q.__webglTexture||S.depthTexture.image.width!==S.width||S.depthTexture.image.height!==S.height)&&(S.depthTexture.image.width=S.width,S.depthTexture.image.height=S.height,S.depthTexture.needsUpdate=!0),V(S.depthTexture,0);const ee=Q.__webglTexture,Z=je(S);if(S.depthTexture.format===Dn)Oe(S)?o.framebufferTexture2DMultisampleEXT(n.FRAMEBUFFER,n.DEPTH_ATTACHMENT,n.TEXTURE_2D,ee,0,Z):n.framebufferTexture2D(n.FRAMEBUFFER,n.DEPTH_ATTACHMENT,n.TEXTURE_2D,ee,0);else if(S.depthTexture.format===On)Oe(S)?o.framebufferTexture2DMultisampleEXT(n.FRAMEBUFFER,n.DEPTH_STENCIL_ATTACHMENT,n.TEXTURE_2D,ee,0,Z):n.framebufferTexture2D(n.FRAMEBUFFER,n.DEPTH_STENCIL_ATTACHMENT,n.TEXTURE_2D,ee,0);else throw new Error("Unknown depthTexture format")}function Ae(C){const S=a.get(C),H=C.isWebGLCubeRenderTarget===!0;if(S.__boundDepthTexture!==C.depthTexture){const Q=C.depthTexture;if(S.__depthDisposeCallback&&S.__depthDisposeCallback(),Q){const ee=()=>{delete S.__boundDepthTexture,delete S.__depthDisposeCallback,Q.removeEventListener("dispose",ee)};Q.addEventListener("dispose",ee),S.__depthDisposeCallback=ee}S.__boundDepthTexture=Q}if(C.depthTexture&&!S.__autoAllocateDepthBuffer){if(H)throw new Error("target.depthTexture not supported in Cube render targets");ge(S.__webglFramebuffer,C)}else if(H){S.__webglDepthbuffer=[];for(let Q=0;Q<6;Q++)if(t.bindFramebuffer(n.FRAMEBUFFER,S.__webglFramebuffer[Q]),S.__webglDepthbuffer[Q]===void 0)S.__webglDepthbuffer[Q]=n.createRenderbuffer(),re(S.__webglDepthbuffer[Q],C,!1);else{const ee=C.stencilBuffer?n.DEPTH_STENCIL_ATTACHMENT:n.DEPTH_ATTACHMENT,Z=S.__webglDepthbuffer[Q];n.bindRenderbuffer(n.RENDERBUFFER,Z),n.framebufferRenderbuffer(n.FRAMEBUFFER,ee,n.RENDERBUFFER,Z)}}else if(t.bindFramebuffer(n.FRAMEBUFFER,S.__webglFramebuffer),S.__webglDepthbuffer===void 0)S.__webglDepthbuffer=n.createRenderbuffer(),re(S.__webglDepthbuffer,C,!1);else{const Q=C.stencilBuffer?n.DEPTH_STENCIL_ATTACHMENT:n.DEPTH_ATTACHMENT,ee=S.__webglDepthbuffer;n.bindRenderbuffer(n.RENDERBUFFER,ee),n.framebufferRenderbuffer(n.FRAMEBUFFER,Q,n.RENDERBUFFER,ee)}t.bindFramebuffer(n.FRAMEBUFFER,null)}function Re(C,S,H){const Q=a.get(C);S!==void 0&&se(Q.__webglFramebuffer,C,C.texture,n.COLOR_ATTACHMENT0,n.TEXTURE_2D,0),H!==void 0&&Ae(C)}function We(C){const S=C.texture,H=a.get(C),Q=a.get(S);C.addEventListener("dispose",A);const ee=C.textures,Z=C.isWebGLCubeRenderTarget===!0,ve=ee.length>1;if(ve||(Q.__webglTexture===void 0&&(Q.__webglTexture=n.createTexture()),Q.__version=S.version,s.memory.textures++),Z){H.__webglFramebuffer=[];for(let ce=0;ce<6;ce++)if(S.mipmaps&&S.mipmaps.length>0){H.__webglFramebuffer[ce]=[];for(let be=0;be<S.mipmaps.length;be++)H.__webglFramebuffer[ce][be]=n.createFramebuffer()}else H.__webglFramebuffer[ce]=n.createFramebuffer()}else{if(S.mipmaps&&S.mipmaps.length>0){H.__webglFramebuffer=[];for(let ce=0;ce<S.mipmaps.length;ce++)H.__webglFramebuffer[ce]=n.createFramebuffer()}else H.__webglFramebuffer=n.createFramebuffer();if(ve)for(let ce=0,be=ee.length;ce<be;ce++){const Ge=a.get(ee[ce]);Ge.__webglTexture===void 0&&(Ge.__webglTexture=n.createTexture(),s.memory.textures++)}if(C.samples>0&&Oe(C)===!1){H.__webglMultisampledFramebuffer=n.createFramebuffer(),H.__webglColorRenderbuffer=[],t.bindFramebuffer(n.FRAMEBUFFER,H.__webglMultisampledFramebuffer);for(let ce=0;ce<ee.length;ce++){const be=ee[ce];H.__webglColorRenderbuffer[ce]=n.createRenderbuffer(),n.bindRenderbuffer(n.RENDERBUFFER,H.__webglColorRenderbuffer[ce]);const Ge=r.convert(be.format,be.colorSpace),ae=r.convert(be.type),me=x(be.internalFormat,Ge,ae,be.colorSpace,C.isXRRenderTarget===!0),Se=je(C);n.renderbufferStorageMultisample(n.RENDERBUFFER,Se,me,C.width,C.height),n.framebufferRenderbuffer(n.FRAMEBUFFER,n.COLOR_ATTACHMENT0+ce,n.RENDERBUFFER,H.__webglColorRenderbuffer[ce])}n.bindRenderbuffer(n.RENDERBUFFER,null),C.depthBuffer&&(H.__webglDepthRenderbuffer=n.createRenderbuffer(),re(H.__webglDepthRenderbuffer,C,!0)),t.bindFramebuffer(n.FRAMEBUFFER,null)}}if(Z){t.bindTexture(n.TEXTURE_CUBE_MAP,Q.__webglTexture),pe(n.TEXTURE_CUBE_MAP,S);for(let ce=0;ce<6;ce++)if(S.mipmaps&&S.mipmaps.length>0)for(let be=0;be<S.mipmaps.length;be++)se(H.__webglFramebuffer[ce][be],C,S,n.COLOR_ATTACHMENT0,n.TEXTURE_CUBE_MAP_POSITIVE_X+ce,be);else se(H.__webglFramebuffer[ce],C,S,n.COLOR_ATTACHMENT0,n.TEXTURE_CUBE_MAP_POSITIVE_X+ce,0);m(S)&&u(n.TEXTURE_CUBE_MAP),t.unbindTexture()}else if(ve){for(let ce=0,be=ee.length;ce<be;ce++){const Ge=ee[ce],ae=a.get(Ge);t.bindTexture(n.TEXTURE_2D,ae.__webglTexture),pe(n.TEXTURE_2D,Ge),se(H.__webglFramebuffer,C,Ge,n.COLOR_ATTACHMENT0+ce,n.TEXTURE_2D,0),m(Ge)&&u(n.TEXTURE_2D)}t.unbindTexture()}else{let ce=n.TEXTURE_2D;if((C.isWebGL3DRenderTarget||C.isWebGLArrayRenderTarget)&&(ce=C.isWebGL3DRenderTarget?n.TEXTURE_3D:n.TEXTURE_2D_ARRAY),t.bindTexture(ce,Q.__webglTexture),pe(ce,S),S.mipmaps&&S.mipmaps.length>0)for(let be=0;be<S.mipmaps.length;be++)se(H.__webglFramebuffer[be],C,S,n.COLOR_ATTACHMENT0,ce,be);else se(H.__webglFramebuffer,C,S,n.COLOR_ATTACHMENT0,ce,0);m(S)&&u(ce),t.unbindTexture()}C.depthBuffer&&Ae(C)}function Ie(C){const S=C.textures;for(let H=0,Q=S.length;H<Q;H++){const ee=S[H];if(m(ee)){const Z=y(C),ve=a.get(ee).__webglTexture;t.bindTexture(Z,ve),u(Z),t.unbindTexture()}}}const Ke=[],F=[];function vt(C){if(C.samples>0){if(Oe(C)===!1){const S=C.textures,H=C.width,Q=C.height;let ee=n.COLOR_BUFFER_BIT;const Z=C.stencilBuffer?n.DEPTH_STENCIL_ATTACHMENT:n.DEPTH_ATTACHMENT,ve=a.get(C),ce=S.length>1;if(ce)for(let be=0;be<S.length;be++)t.bindFramebuffer(n.FRAMEBUFFER,ve.__webglMultisampledFramebuffer),n.framebufferRenderbuffer(n.FRAMEBUFFER,n.COLOR_ATTACHMENT0+be,n.RENDERBUFFER,null),t.bindFramebuffer(n.FRAMEBUFFER,ve.__webglFramebuffer),n.framebufferTexture2D(n.DRAW_FRAMEBUFFER,n.COLOR_ATTACHMENT0+be,n.TEXTURE_2D,null,0);t.bindFramebuffer(n.READ_FRAMEBUFFER,ve.__webglMultisampledFramebuffer),t.bindFramebuffer(n.DRAW_FRAMEBUFFER,ve.__webglFramebuffer);for(let be=0;be<S.length;be++){if(C.resolveDepthBuffer&&(C.depthBuffer&&(ee|=n.DEPTH_BUFFER_BIT),C.stencilBuffer&&C.resolveStencilBuffer&&(ee|=n.STENCIL_BUFFER_BIT)),ce){n.framebufferRenderbuffer(n.READ_FRAMEBUFFER,n.COLOR_ATTACHMENT0,n.RENDERBUFFER,ve.__webglColorRenderbuffer[be]);const Ge=a.get(S[be]).__webglTexture;n.framebufferTexture2D(n.DRAW_FRAMEBUFFER,n.COLOR_ATTACHMENT0,n.TEXTURE_2D,Ge,0)}n.blitFramebuffer(0,0,H,Q,0,0,H,Q,ee,n.NEAREST),c===!0&&(Ke.length=0,F.length=0,Ke.push(n.COLOR_ATTACHMENT0+be),C.depthBuffer&&C.resolveDepthBuffer===!1&&(Ke.push(Z),F.push(Z),n.invalidateFramebuffer(n.DRAW_FRAMEBUFFER,F)),n.invalidateFramebuffer(n.READ_FRAMEBUFFER,Ke))}if(t.bindFramebuffer(n.READ_FRAMEBUFFER,null),t.bindFramebuffer(n.DRAW_FRAMEBUFFER,null),ce)for(let be=0;be<S.length;be++){t.bindFramebuffer(n.FRAMEBUFFER,ve.__webglMultisampledFramebuffer),n.framebufferRenderbuffer(n.FRAMEBUFFER,n.COLOR_ATTACHMENT0+be,n.RENDERBUFFER,ve.__webglColorRenderbuffer[be]);const Ge=a.get(S[be]).__webglTexture;t.bindFramebuffer(n.FRAMEBUFFER,ve.__webglFramebuffer),n.framebufferTexture2D(n.DRAW_FRAMEBUFFER,n.COLOR_ATTACHMENT0+be,n.TEXTURE_2D,Ge,0)}t.bindFramebuffer(n.DRAW_FRAMEBUFFER,ve.__webglMultisampledFramebuffer)}else if(C.depthBuffer&&C.resolveDepthBuffer===!1&&c){const S=C.stencilBuffer?n.DEPTH_STENCIL_ATTACHMENT:n.DEPTH_ATTACHMENT;n.invalidateFramebuffer(n.DRAW_FRAMEBUFFER,[S])}}}function je(C){return Math.min(i.maxSamples,C.samples)}function Oe(C){const S=a.get(C);return C.samples>0&&e.has("WEBGL_multisampled_render_to_texture")===!0&&S.__useRenderToTexture!==!1}function Ee(C){const S=s.render.frame;h.get(C)!==S&&(h.set(C,S),C.update())}function Ze(C,S){const H=C.colorSpace,Q=C.format,ee=C.type;return C.isCompressedTexture===!0||C.isVideoTexture===!0||H!==Hn&&H!==ga&&(qe.getTransfer(H)===et?(Q!==Rt||ee!==_a)&&console.warn("THREE.WebGLTextures: sRGB encoded textures have to use RGBAFormat and UnsignedByteType."):console.error("THREE.WebGLTextures: Unsupported texture color space:",H)),S}function _e(C){return typeof HTMLImageElement<"u"&&C instanceof HTMLImageElement?(l.width=C.naturalWidth||C.width,l.height=C.naturalHeight||C.height):typeof VideoFrame<"u"&&C instanceof VideoFrame?(l.width=C.displayWidth,l.height=C.displayHeight):(l.width=C.width,l.height=C.height),l}this.allocateTextureUnit=P,this.resetTextureUnits=U,this.setTexture2D=V,this.setTexture2DArray=B,this.setTexture3D=G,this.setTextureCube=z,this.rebindTextures=Re,this.setupRenderTarget=We,this.updateRenderTargetMipmap=Ie,this.updateMultisampleRenderTarget=vt,this.setupDepthRenderbuffer=Ae,this.setupFrameBufferTexture=se,this.useMultisampledRTT=Oe}function by(n,e){function t(a,i=ga){let r;const s=qe.getTransfer(i);if(a===_a)return n.UNSIGNED_BYTE;if(a===No)return n.UNSIGNED_SHORT_4_4_4_4;if(a===Uo)return n.UNSIGNED_SHORT_5_5_5_1;if(a===jl)return n.UNSIGNED_INT_5_9_9_9_REV;if(a===Fl)return n.BYTE;if(a===Ll)return n.SHORT;if(a===vi)return n.UNSIGNED_SHORT;if(a===Do)return n.INT;if(a===sn)return n.UNSIGNED_INT;if(a===zt)return n.FLOAT;if(a===Si)return n.HALF_FLOAT;if(a===Ol)return n.ALPHA;if(a===zl)return n.RGB;if(a===Rt)return n.RGBA;if(a===Bl)return n.LUMINANCE;if(a===Gl)return n.LUMINANCE_ALPHA;if(a===Dn)return n.DEPTH_COMPONENT;if(a===On)return n.DEPTH_STENCIL;if(a===Hl)return n.RED;if(a===Fo)return n.RED_INTEGER;if(a===Vl)return n.RG;if(a===Lo)return n.RG_INTEGER;if(a===jo)return n.RGBA_INTEGER;if(a===sr||a===or||a===cr||a===hr)if(s===et)if(r=e.get("WEBGL_compressed_texture_s3tc_srgb"),r!==null){if(a===sr)return r.COMPRESSED_SRGB_S3TC_DXT1_EXT;if(a===or)return r.COMPRESSED_SRGB_ALPHA_S3TC_DXT1_EXT;if(a===cr)return r.COMPRESSED_SRGB_ALPHA_S3TC_DXT3_EXT;if(a===hr)return r.COMPRESSED_SRGB_ALPHA_S3TC_DXT5_EXT}else return null;else if(r=e.get("WEBGL_compressed_texture_s3tc"),r!==null){if(a===sr)return r.COMPRESSED_RGB_S3TC_DXT1_EXT;if(a===or)return r.COMPRESSED_RGBA_S3TC_DXT1_EXT;if(a===cr)return r.COMPRESSED_RGBA_S3TC_DXT3_EXT;if(a===hr)return r.COMPRESSED_RGBA_S3TC_DXT5_EXT}else return null;if(a===Hs||a===Vs||a===Ws||a===qs)if(r=e.get("WEBGL_compressed_texture_pvrtc"),r!==null){if(a===Hs)return r.COMPRESSED_RGB_PVRTC_4BPPV1_IMG;if(a===Vs)return r.COMPRESSED_RGB_PVRTC_2BPPV1_IMG;if(a===Ws)return r.COMPRESSED_RGBA_PVRTC_4BPPV1_IMG;if(a===qs)return r.COMPRESSED_RGBA_PVRTC_2BPPV1_IMG}else return null;if(a===Xs||a===Ks||a===Js)if(r=e.get("WEBGL_compressed_texture_etc"),r!==null){if(a===Xs||a===Ks)return s===et?r.COMPRESSED_SRGB8_ETC2:r.COMPRESSED_RGB8_ETC2;if(a===Js)return s===et?r.COMPRESSED_SRGB8_ALPHA8_ETC2_EAC:r.COMPRESSED_RGBA8_ETC2_EAC}else return null;if(a===Ys||a===Zs||a===Qs||a===$s||a===eo||a===to||a===ao||a===no||a===io||a===ro||a===so||a===oo||a===co||a===ho)if(r=e.get("WEBGL_compressed_texture_astc"),r!==null){if(a===Ys)return s===et?r.COMPRESSED_SRGB8_ALPHA8_ASTC_4x4_KHR:r.COMPRESSED_RGBA_ASTC_4x4_KHR;if(a===Zs)return s===et?r.COMPRESSED_SRGB8_ALPHA8_ASTC_5x4_KHR:r.COMPRESSED_RGBA_ASTC_5x4_KHR;if(a===Qs)return s===et?r.COMPRESSED_SRGB8_ALPHA8_ASTC_5x5_KHR:r.COMPRESSED_RGBA_ASTC_5x5_KHR;if(a===$s)return s===et?r.COMPRESSED_SRGB8_ALPHA8_ASTC_6x5_KHR:r.COMPRESSED_RGBA_ASTC_6x5_KHR;if(a===eo)return s===et?r.COMPRESSED_SRGB8_ALPHA8_ASTC_6x6_KHR:r.COMPRESSED_RGBA_ASTC_6x6_KHR;if(a===to)return s===et?r.COMPRESSED_SRGB8_ALPHA8_ASTC_8x5_KHR:r.COMPRESSED_RGBA_ASTC_8x5_KHR;if(a===ao)return s===et?r.COMPRESSED_SRGB8_ALPHA8_ASTC_8x6_KHR:r.COMPRESSED_RGBA_ASTC_8x6_KHR;if(a===no)return s===et?r.COMPRESSED_SRGB8_ALPHA8_ASTC_8x8_KHR:r.COMPRESSED_RGBA_ASTC_8x8_KHR;if(a===io)return s===et?r.COMPRESSED_SRGB8_ALPHA8_ASTC_10x5_KHR:r.COMPRESSED_RGBA_ASTC_10x5_KHR;if(a===ro)return s===et?r.COMPRESSED_SRGB8_ALPHA8_ASTC_10x6_KHR:r.COMPRESSED_RGBA_ASTC_10x6_KHR;if(a===so)return s===et?r.COMPRESSED_SRGB8_ALPHA8_ASTC_10x8_KHR:r.COMPRESSED_RGBA_ASTC_10x8_KHR;if(a===oo)return s===et?r.COMPRESSED_SRGB8_ALPHA8_ASTC_10x10_KHR:r.COMPRESSED_RGBA_ASTC_10x10_KHR;if(a===co)return s===et?r.COMPRESSED_SRGB8_ALPHA8_ASTC_12x10_KHR:r.COMPRESSED_RGBA_ASTC_12x10_KHR;if(a===ho)return s===et?r.COMPRESSED_SRGB8_ALPHA8_ASTC_12x12_KHR:r.COMPRESSED_RGBA_ASTC_12x12_KHR}else return null;if(a===lr||a===lo||a===fo)if(r=e.get("EXT_texture_compression_bptc"),r!==null){if(a===lr)return s===et?r.COMPRESSED_SRGB_ALPHA_BPTC_UNORM_EXT:r.COMPRESSED_RGBA_BPTC_UNORM_EXT;if(a===lo)return r.COMPRESSED_RGB_BPTC_SIGNED_FLOAT_EXT;if(a===fo)return r.COMPRESSED_RGB_BPTC_UNSIGNED_FLOAT_EXT}else return null;if(a===Wl||a===uo||a===bo||a===mo)if(r=e.get("EXT_texture_compression_rgtc"),r!==null){if(a===lr)return r.COMPRESSED_RED_RGTC1_EXT;if(a===uo)return r.COMPRESSED_SIGNED_RED_RGTC1_EXT;if(a===bo)return r.COMPRESSED_RED_GREEN_RGTC2_EXT;if(a===mo)return r.COMPRESSED_SIGNED_RED_GREEN_RGTC2_EXT}else return null;return a===jn?n.UNSIGNED_INT_24_8:n[a]!==void 0?n[a]:null}return{convert:t}}class my extends Pt{constructor(e=[]){super(),this.isArrayCamera=!0,this.cameras=e}}class di extends Et{constructor(){super(),this.isGroup=!0,this.type="Group"}}const py={type:"move"};class ds{constructor(){this._targetRay=null,this._grip=null,this._hand=null}getHandSpace(){return this._hand===null&&(this._hand=new di,this._hand.matrixAutoUpdate=!1,this._hand.visible=!1,this._hand.joints={},this._hand.inputState={pinching:!1}),this._hand}getTargetRaySpace(){return this._targetRay===null&&(this._targetRay=new di,this._targetRay.matrixAutoUpdate=!1,this._targetRay.visible=!1,this._targetRay.hasLinearVelocity=!1,this._targetRay.linearVelocity=new O,this._targetRay.hasAngularVelocity=!1,this._targetRay.angularVelocity=new O),this._targetRay}getGripSpace(){return this._grip===null&&(this._grip=new di,this._grip.matrixAutoUpdate=!1,this._grip.visible=!1,this._grip.hasLinearVelocity=!1,this._grip.linearVelocity=new O,this._grip.hasAngularVelocity=!1,this._grip.angularVelocity=new O),this._grip}dispatchEvent(e){return this._targetRay!==null&&this._targetRay.dispatchEvent(e),this._grip!==null&&this._grip.dispatchEvent(e),this._hand!==null&&this._hand.dispatchEvent(e),this}connect(e){if(e&&e.hand){const t=this._hand;if(t)for(const a of e.hand.values())this._getHandJoint(t,a)}return this.dispatchEvent({type:"connected",data:e}),this}disconnect(e){return this.dispatchEvent({type:"disconnected",data:e}),this._targetRay!==null&&(this._targetRay.visible=!1),this._grip!==null&&(this._grip.visible=!1),this._hand!==null&&(this._hand.visible=!1),this}update(e,t,a){let i=null,r=null,s=null;const o=this._targetRay,c=this._grip,l=this._hand;if(e&&t.session.visibilityState!=="visible-blurred"){if(l&&e.hand){s=!0;for(const g of e.hand.values()){const m=t.getJointPose(g,a),u=this._getHandJoint(l,g);m!==null&&(u.matrix.fromArray(m.transform.matrix),u.matrix.decompose(u.position,u.rotation,u.scale),u.matrixWorldNeedsUpdate=!0,u.jointRadius=m.radius),u.visible=m!==null}const h=l.joints["index-finger-tip"],d=l.joints["thumb-tip"],f=h.position.distanceTo(d.position),b=.02,p=.005;l.inputState.pinching&&f>b+p?(l.inputState.pinching=!1,this.dispatchEvent({type:"pinchend",handedness:e.handedness,target:this})):!l.inputState.pinching&&f<=b-p&&(l.inputState.pinching=!0,this.dispatchEvent({type:"pinchstart",handedness:e.handedness,target:this}))}else c!==null&&e.gripSpace&&(r=t.getPose(e.gripSpace,a),r!==null&&(c.matrix.fromArray(r.transform.matrix),c.matrix.decompose(c.position,c.rotation,c.scale),c.matrixWorldNeedsUpdate=!0,r.linearVelocity?(c.hasLinearVelocity=!0,c.linearVelocity.copy(r.linearVelocity)):c.hasLinearVelocity=!1,r.angularVelocity?(c.hasAngularVelocity=!0,c.angularVelocity.copy(r.angularVelocity)):c.hasAngularVelocity=!1));o!==null&&(i=t.getPose(e.targetRaySpace,a),i===null&&r!==null&&(i=r),i!==null&&(o.matrix.fromArray(i.transform.matrix),o.matrix.decompose(o.position,o.rotation,o.scale),o.matrixWorldNeedsUpdate=!0,i.linearVelocity?(o.hasLinearVelocity=!0,o.linearVelocity.copy(i.linearVelocity)):o.hasLinearVelocity=!1,i.angularVelocity?(o.hasAngularVelocity=!0,o.angularVelocity.copy(i.angularVelocity)):o.hasAngularVelocity=!1,this.dispatchEvent(py)))}return o!==null&&(o.visible=i!==null),c!==null&&(c.visible=r!==null),l!==null&&(l.visible=s!==null),this}_getHandJoint(e,t){if(e.joints[t.jointName]===void 0){const a=new di;a.matrixAutoUpdate=!1,a.visible=!1,e.joints[t.jointName]=a,e.add(a)}return e.joints[t.jointName]}}const gy=`
void main() {

	gl_Position = vec4( position, 1.0 );

}`,vy=`
uniform sampler2DArray depthColor;
uniform float depthWidth;
uniform float depthHeight;

void main() {

	vec2 coord = vec2( gl_FragCoord.x / depthWidth, gl_FragCoord.y / depthHeight );

	if ( coord.x >= 1.0 ) {

		gl_FragDepth = texture( depthColor, vec3( coord.x - 1.0, coord.y, 1 ) ).r;

	} else {

		gl_FragDepth = texture( depthColor, vec3( coord.x, coord.y, 0 ) ).r;

	}

}`;class yy{constructor(){this.texture=null,this.mesh=null,this.depthNear=0,this.depthFar=0}init(e,t,a){if(this.texture===null){const i=new _t,r=e.properties.get(i);r.__webglTexture=t.texture,(t.depthNear!=a.depthNear||t.depthFar!=a.depthFar)&&(this.depthNear=t.depthNear,this.depthFar=t.depthFar),this.texture=i}}getMesh(e){if(this.texture!==null&&this.mesh===null){const t=e.cameras[0].viewport,a=new Jt({vertexShader:gy,fragmentShader:vy,uniforms:{depthColor:{value:this.texture},depthWidth:{value:t.z},depthHeight:{value:t.w}}});this.mesh=new Nt(new Bn(20,20),a)}return this.mesh}reset(){this.texture=null,this.mesh=null}getDepthTexture(){return this.texture}}class xy extends hn{constructor(e,t){super();const a=this;let i=null,r=1,s=null,o="local-floor",c=1,l=null,h=null,d=null,f=null,b=null,p=null;const g=new yy,m=t.getContextAttributes();let u=null,y=null;const x=[],v=[],E=new De;let _=null;const A=new Pt;A.viewport=new ot;const k=new Pt;k.viewport=new ot;const w=[A,k],M=new my;let R=null,U=null;this.cameraAutoUpdate=!0,this.enabled=!1,this.isPresenting=!1,this.getController=function(W){let J=x[W];return J===void 0&&(J=new ds,x[W]=J),J.getTargetRaySpace()},this.getControllerGrip=function(W){let J=x[W];return J===void 0&&(J=new ds,x[W]=J),J.getGripSpace()},this.getHand=function(W){let J=x[W];return J===void 0&&(J=new ds,x[W]=J),J.getHandSpace()};function P(W){const J=v.indexOf(W.inputSource);if(J===-1)return;const se=x[J];se!==void 0&&(se.update(W.inputSource,W.frame,l||s),se.dispatchEvent({type:W.type,data:W.inputSource}))}function D(){i.removeEventListener("select",P),i.removeEventListener("selectstart",P),i.removeEventListener("selectend",P),i.removeEventListener("squeeze",P),i.removeEventListener("squeezestart",P),i.removeEventListener("squeezeend",P),i.removeEventListener("end",D),i.removeEventListener("inputsourceschange",V);for(let W=0;W<x.length;W++){const J=v[W];J!==null&&(v[W]=null,x[W].disconnect(J))}R=null,U=null,g.reset(),e.setRenderTarget(u),b=null,f=null,d=null,i=null,y=null,Te.stop(),a.isPresenting=!1,e.setPixelRatio(_),e.setSize(E.width,E.height,!1),a.dispatchEvent({type:"sessionend"})}this.setFramebufferScaleFactor=function(W){r=W,a.isPresenting===!0&&console.warn("THREE.WebXRManager: Cannot change framebuffer scale while presenting.")},this.setReferenceSpaceType=function(W){o=W,a.isPresenting===!0&&console.warn("THREE.WebXRManager: Cannot change reference space type while presenting.")},this.getReferenceSpace=function(){return l||s},this.setReferenceSpace=function(W){l=W},this.getBaseLayer=function(){return f!==null?f:b},this.getBinding=function(){return d},this.getFrame=function(){return p},this.getSession=function(){return i},this.setSession=async function(W){if(i=W,i!==null){if(u=e.getRenderTarget(),i.addEventListener("select",P),i.addEventListener("selectstart",P),i.addEventListener("selectend",P),i.addEventListener("squeeze",P),i.addEventListener("squeezestart",P),i.addEventListener("squeezeend",P),i.addEventListener("end",D),i.addEventListener("inputsourceschange",V),m.xrCompatible!==!0&&await t.makeXRCompatible(),_=e.getPixelRatio(),e.getSize(E),i.renderState.layers===void 0){const J={antialias:m.antialias,alpha:!0,depth:m.depth,stencil:m.stencil,framebufferScaleFactor:r};b=new XRWebGLLayer(i,t,J),i.updateRenderState({baseLayer:b}),e.setPixelRatio(1),e.setSize(b.framebufferWidth,b.framebufferHeight,!1),y=new Sa(b.framebufferWidth,b.framebufferHeight,{format:Rt,type:_a,colorSpace:e.outputColorSpace,stencilBuffer:m.stencil})}else{let J=null,se=null,re=null;m.depth&&(re=m.stencil?t.DEPTH24_STENCIL8:t.DEPTH_COMPONENT24,J=m.stencil?On:Dn,se=m.stencil?jn:sn);const ge={colorFormat:t.RGBA8,depthFormat:re,scaleFactor:r};d=new XRWebGLBinding(i,t),f=d.createProjectionLayer(ge),i.updateRenderState({layers:[f]}),e.setPixelRatio(1),e.setSize(f.textureWidth,f.textureHeight,!1),y=new Sa(f.textureWidth,f.textureHeight,{format:Rt,type:_a,depthTexture:new od(f.textureWidth,f.textureHeight,se,void 0,void 0,void 0,void 0,void 0,void 0,J),stencilBuffer:m.stencil,colorSpace:e.outputColorSpace,samples:m.antialias?4:0,resolveDepthBuffer:f.ignoreDepthValues===!1})}y.isXRRenderTarget=!0,this.setFoveation(c),l=null,s=await i.requestReferenceSpace(o),Te.setContext(i),Te.start(),a.isPresenting=!0,a.dispatchEvent({type:"sessionstart"})}},this.getEnvironmentBlendMode=function(){if(i!==null)return i.environmentBlendMode},this.getDepthTexture=function(){return g.getDepthTexture()};function V(W){for(let J=0;J<W.removed.length;J++){const se=W.removed[J],re=v.indexOf(se);re>=0&&(v[re]=null,x[re].disconnect(se))}for(let J=0;J<W.added.length;J++){const se=W.added[J];let re=v.indexOf(se);if(re===-1){for(let Ae=0;Ae<x.length;Ae++)if(Ae>=v.length){v.push(se),re=Ae;break}else if(v[Ae]===null){v[Ae]=se,re=Ae;break}if(re===-1)break}const ge=x[re];ge&&ge.connect(se)}}const B=new O,G=new O;function z(W,J,se){B.setFromMatrixPosition(J.matrixWorld),G.setFromMatrixPosition(se.matrixWorld);const re=B.distanceTo(G),ge=J.projectionMatrix.elements,Ae=se.projectionMatrix.elements,Re=ge[14]/(ge[10]-1),We=ge[14]/(ge[10]+1),Ie=(ge[9]+1)/ge[5],Ke=(ge[9]-1)/ge[5],F=(ge[8]-1)/ge[0],vt=(Ae[8]+1)/Ae[0],je=Re*F,Oe=Re*vt,Ee=re/(-F+vt),Ze=Ee*-F;if(J.matrixWorld.decompose(W.position,W.quaternion,W.scale),W.translateX(Ze),W.translateZ(Ee),W.matrixWorld.compose(W.position,W.quaternion,W.scale),W.matrixWorldInverse.copy(W.matrixWorld).invert(),ge[10]===-1)W.projectionMatrix.copy(J.projectionMatrix),W.projectionMatrixInverse.copy(J.projectionMatrixInverse);else{const _e=Re+Ee,C=We+Ee,S=je-Ze,H=Oe+(re-Ze),Q=Ie*We/C*_e,ee=Ke*We/C*_e;W.projectionMatrix.makePerspective(S,H,Q,ee,_e,C),W.projectionMatrixInverse.copy(W.projectionMatrix).invert()}}function Y(W,J){J===null?W.matrixWorld.copy(W.matrix):W.matrixWorld.multiplyMatrices(J.matrixWorld,W.matrix),W.matrixWorldInverse.copy(W.matrixWorld).invert()}this.updateCamera=function(W){if(i===null)return;let J=W.near,se=W.far;g.texture!==null&&(g.depthNear>0&&(J=g.depthNear),g.depthFar>0&&(se=g.depthFar)),M.near=k.near=A.near=J,M.far=k.far=A.far=se,(R!==M.near||U!==M.far)&&(i.updateRenderState({depthNear:M.near,depthFar:M.far}),R=M.near,U=M.far),A.layers.mask=W.layers.mask|2,k.layers.mask=W.layers.mask|4,M.layers.mask=A.layers.mask|k.layers.mask;const re=W.parent,ge=M.cameras;Y(M,re);for(let Ae=0;Ae<ge.length;Ae++)Y(ge[Ae],re);ge.length===2?z(M,A,k):M.projectionMatrix.copy(A.projectionMatrix),te(W,M,re)};function te(W,J,se){se===null?W.matrix.copy(J.matrixWorld):(W.matrix.copy(se.matrixWorld),W.matrix.invert(),W.matrix.multiply(J.matrixWorld)),W.matrix.decompose(W.position,W.quaternion,W.scale),W.updateMatrixWorld(!0),W.projectionMatrix.copy(J.projectionMatrix),W.projectionMatrixInverse.copy(J.projectionMatrixInverse),W.isPerspectiveCamera&&(W.fov=yi*2*Math.atan(1/W.projectionMatrix.elements[5]),W.zoom=1)}this.getCamera=function(){return M},this.getFoveation=function(){if(!(f===null&&b===null))return c},this.setFoveation=function(W){c=W,f!==null&&(f.fixedFoveation=W),b!==null&&b.fixedFoveation!==void 0&&(b.fixedFoveation=W)},this.hasDepthSensing=function(){return g.texture!==null},this.getDepthSensingMesh=function(){return g.getMesh(M)};let ie=null;function pe(W,J){if(h=J.getViewerPose(l||s),p=J,h!==null){const se=h.views;b!==null&&(e.setRenderTargetFramebuffer(y,b.framebuffer),e.setRenderTarget(y));let re=!1;se.length!==M.cameras.length&&(M.cameras.length=0,re=!0);for(let Ae=0;Ae<se.length;Ae++){const Re=se[Ae];let We=null;if(b!==null)We=b.getViewport(Re);else{const Ke=d.getViewSubImage(f,Re);We=Ke.viewport,Ae===0&&(e.setRenderTargetTextures(y,Ke.colorTexture,f.ignoreDepthValues?void 0:Ke.depthStencilTexture),e.setRenderTarget(y))}let Ie=w[Ae];Ie===void 0&&(Ie=new Pt,Ie.layers.enable(Ae),Ie.viewport=new ot,w[Ae]=Ie),Ie.matrix.fromArray(Re.transform.matrix),Ie.matrix.decompose(Ie.position,Ie.quaternion,Ie.scale),Ie.projectionMatrix.fromArray(Re.projectionMatrix),Ie.projectionMatrixInverse.copy(Ie.projectionMatrix).invert(),Ie.viewport.set(We.x,We.y,We.width,We.height),Ae===0&&(M.matrix.copy(Ie.matrix),M.matrix.decompose(M.position,M.quaternion,M.scale)),re===!0&&M.cameras.push(Ie)}const ge=i.enabledFeatures;if(ge&&ge.includes("depth-sensing")){const Ae=d.getDepthInformation(se[0]);Ae&&Ae.isValid&&Ae.texture&&g.init(e,Ae,i.renderState)}}for(let se=0;se<x.length;se++){const re=v[se],ge=x[se];re!==null&&ge!==void 0&&ge.update(re,J,l||s)}ie&&ie(W,J),J.detectedPlanes&&a.dispatchEvent({type:"planesdetected",data:J}),p=null}const Te=new sd;Te.setAnimationLoop(pe),this.setAnimationLoop=function(W){ie=W},this.dispose=function(){}}}const Qa=new Aa,wy=new ze;function My(n,e){function t(m,u){m.matrixAutoUpdate===!0&&m.updateMatrix(),u.value.copy(m.matrix)}function a(m,u){u.color.getRGB(m.fogColor.value,ad(n)),u.isFog?(m.fogNear.value=u.near,m.fogFar.value=u.far):u.isFogExp2&&(m.fogDensity.value=u.density)}function i(m,u,y,x,v){u.isMeshBasicMaterial||u.isMeshLambertMaterial?r(m,u):u.isMeshToonMaterial?(r(m,u),d(m,u)):u.isMeshPhongMaterial?(r(m,u),h(m,u)):u.isMeshStandardMaterial?(r(m,u),f(m,u),u.isMeshPhysicalMaterial&&b(m,u,v)):u.isMeshMatcapMaterial?(r(m,u),p(m,u)):u.isMeshDepthMaterial?r(m,u):u.isMeshDistanceMaterial?(r(m,u),g(m,u)):u.isMeshNormalMaterial?r(m,u):u.isLineBasicMaterial?(s(m,u),u.isLineDashedMaterial&&o(m,u)):u.isPointsMaterial?c(m,u,y,x):u.isSpriteMaterial?l(m,u):u.isShadowMaterial?(m.color.value.copy(u.color),m.opacity.value=u.opacity):u.isShaderMaterial&&(u.uniformsNeedUpdate=!1)}function r(m,u){m.opacity.value=u.opacity,u.color&&m.diffuse.value.copy(u.color),u.emissive&&m.emissive.value.copy(u.emissive).multiplyScalar(u.emissiveIntensity),u.map&&(m.map.value=u.map,t(u.map,m.mapTransform)),u.alphaMap&&(m.alphaMap.value=u.alphaMap,t(u.alphaMap,m.alphaMapTransform)),u.bumpMap&&(m.bumpMap.value=u.bumpMap,t(u.bumpMap,m.bumpMapTransform),m.bumpScale.value=u.bumpScale,u.side===Ut&&(m.bumpScale.value*=-1)),u.normalMap&&(m.normalMap.value=u.normalMap,t(u.normalMap,m.normalMapTransform),m.normalScale.value.copy(u.normalScale),u.side===Ut&&m.normalScale.value.negate()),u.displacementMap&&(m.displacementMap.value=u.displacementMap,t(u.displacementMap,m.displacementMapTransform),m.displacementScale.value=u.displacementScale,m.displacementBias.value=u.displacementBias),u.emissiveMap&&(m.emissiveMap.value=u.emissiveMap,t(u.emissiveMap,m.emissiveMapTransform)),u.specularMap&&(m.specularMap.value=u.specularMap,t(u.specularMap,m.specularMapTransform)),u.alphaTest>0&&(m.alphaTest.value=u.alphaTest);const y=e.get(u),x=y.envMap,v=y.envMapRotation;x&&(m.envMap.value=x,Qa.copy(v),Qa.x*=-1,Qa.y*=-1,Qa.z*=-1,x.isCubeTexture&&x.isRenderTargetTexture===!1&&(Qa.y*=-1,Qa.z*=-1),m.envMapRotation.value.setFromMatrix4(wy.makeRotationFromEuler(Qa)),m.flipEnvMap.value=x.isCubeTexture&&x.isRenderTargetTexture===!1?-1:1,m.reflectivity.value=u.reflectivity,m.ior.value=u.ior,m.refractionRatio.value=u.refractionRatio),u.lightMap&&(m.lightMap.value=u.lightMap,m.lightMapIntensity.value=u.lightMapIntensity,t(u.lightMap,m.lightMapTransform)),u.aoMap&&(m.aoMap.value=u.aoMap,m.aoMapIntensity.value=u.aoMapIntensity,t(u.aoMap,m.aoMapTransform))}function s(m,u){m.diffuse.value.copy(u.color),m.opacity.value=u.opacity,u.map&&(m.map.value=u.map,t(u.map,m.mapTransform))}function o(m,u){m.dashSize.value=u.dashSize,m.totalSize.value=u.dashSize+u.gapSize,m.scale.value=u.scale}function c(m,u,y,x){m.diffuse.value.copy(u.color),m.opacity.value=u.opacity,m.size.value=u.size*y,m.scale.value=x*.5,u.map&&(m.map.value=u.map,t(u.map,m.uvTransform)),u.alphaMap&&(m.alphaMap.value=u.alphaMap,t(u.alphaMap,m.alphaMapTransform)),u.alphaTest>0&&(m.alphaTest.value=u.alphaTest)}function l(m,u){m.diffuse.value.copy(u.color),m.opacity.value=u.opacity,m.rotation.value=u.rotation,u.map&&(m.map.value=u.map,t(u.map,m.mapTransform)),u.alphaMap&&(m.alphaMap.value=u.alphaMap,t(u.alphaMap,m.alphaMapTransform)),u.alphaTest>0&&(m.alphaTest.value=u.alphaTest)}function h(m,u){m.specular.value.copy(u.specular),m.shininess.value=Math.max(u.shininess,1e-4)}function d(m,u){u.gradientMap&&(m.gradientMap.value=u.gradientMap)}function f(m,u){m.metalness.value=u.metalness,u.metalnessMap&&(m.metalnessMap.value=u.metalnessMap,t(u.metalnessMap,m.metalnessMapTransform)),m.roughness.value=u.roughness,u.roughnessMap&&(m.roughnessMap.value=u.roughnessMap,t(u.roughnessMap,m.roughnessMapTransform)),u.envMap&&(m.envMapIntensity.value=u.envMapIntensity)}function b(m,u,y){m.ior.value=u.ior,u.sheen>0&&(m.sheenColor.value.copy(u.sheenColor).multiplyScalar(u.sheen),m.sheenRoughness.value=u.sheenRoughness,u.sheenColorMap&&(m.sheenColorMap.value=u.sheenColorMap,t(u.sheenColorMap,m.sheenColorMapTransform)),u.sheenRoughnessMap&&(m.sheenRoughnessMap.value=u.sheenRoughnessMap,t(u.sheenRoughnessMap,m.sheenRoughnessMapTransform))),u.clearcoat>0&&(m.clearcoat.value=u.clearcoat,m.clearcoatRoughness.value=u.clearcoatRoughness,u.clearcoatMap&&(m.clearcoatMap.value=u.clearcoatMap,t(u.clearcoatMap,m.clearcoatMapTransform)),u.clearcoatRoughnessMap&&(m.clearcoatRoughnessMap.value=u.clearcoatRoughnessMap,t(u.clearcoatRoughnessMap,m.clearcoatRoughnessMapTransform)),u.clearcoatNormalMap&&(m.clearcoatNormalMap.value=u.clearcoatNormalMap,t(u.clearcoatNormalMap,m.clearcoatNormalMapTransform),m.clearcoatNormalScale.value.copy(u.clearcoatNormalScale),u.side===Ut&&m.clearcoatNormalScale.value.negate())),u.dispersion>0&&(m.dispersion.value=u.dispersion),u.iridescence>0&&(m.iridescence.value=u.iridescence,m.iridescenceIOR.value=u.iridescenceIOR,m.iridescenceThicknessMinimum.value=u.iridescenceThicknessRange[0],m.iridescenceThicknessMaximum.value=u.iridescenceThicknessRange[1],u.iridescenceMap&&(m.iridescenceMap.value=u.iridescenceMap,t(u.iridescenceMap,m.iridescenceMapTransform)),u.iridescenceThicknessMap&&(m.iridescenceThicknessMap.value=u.iridescenceThicknessMap,t(u.iridescenceThicknessMap,m.iridescenceThicknessMapTransform))),u.transmission>0&&(m.transmission.value=u.transmission,m.transmissionSamplerMap.value=y.texture,m.transmissionSamplerSize.value.set(y.width,y.height),u.transmissionMap&&(m.transmissionMap.value=u.transmissionMap,t(u.transmissionMap,m.transmissionMapTransform)),m.thickness.value=u.thickness,u.thicknessMap&&(m.thicknessMap.value=u.thicknessMap,t(u.thicknessMap,m.thicknessMapTransform)),m.attenuationDistance.value=u.attenuationDistance,m.attenuationColor.value.copy(u.attenuationColor)),u.anisotropy>0&&(m.anisotropyVector.value.set(u.anisotropy*Math.cos(u.anisotropyRotation),u.anisotropy*Math.sin(u.anisotropyRotation)),u.anisotropyMap&&(m.anisotropyMap.value=u.anisotropyMap,t(u.anisotropyMap,m.anisotropyMapTransform))),m.specularIntensity.value=u.specularIntensity,m.specularColor.value.copy(u.specularColor),u.specularColorMap&&(m.specularColorMap.value=u.specularColorMap,t(u.specularColorMap,m.specularColorMapTransform)),u.specularIntensityMap&&(m.specularIntensityMap.value=u.specularIntensityMap,t(u.specularIntensityMap,m.specularIntensityMapTransform))}function p(m,u){u.matcap&&(m.matcap.value=u.matcap)}function g(m,u){const y=e.get(u).light;m.referencePosition.value.setFromMatrixPosition(y.matrixWorld),m.nearDistance.value=y.shadow.camera.near,m.farDistance.value=y.shadow.camera.far}return{refreshFogUniforms:a,refreshMaterialUniforms:i}}function _y(n,e,t,a){let i={},r={},s=[];const o=n.getParameter(n.MAX_UNIFORM_BUFFER_BINDINGS);function c(y,x){const v=x.program;a.uniformBlockBinding(y,v)}function l(y,x){let v=i[y.id];v===void 0&&(p(y),v=h(y),i[y.id]=v,y.addEventListener("dispose",m));const E=x.program;a.updateUBOMapping(y,E);const _=e.render.frame;r[y.id]!==_&&(f(y),r[y.id]=_)}function h(y){const x=d();y.__bindingPointIndex=x;const v=n.createBuffer(),E=y.__size,_=y.usage;return n.bindBuffer(n.UNIFORM_BUFFER,v),n.bufferData(n.UNIFORM_BUFFER,E,_),n.bindBuffer(n.UNIFORM_BUFFER,null),n.bindBufferBase(n.UNIFORM_BUFFER,x,v),v}function d(){for(let y=0;y<o;y++)if(s.indexOf(y)===-1)return s.push(y),y;return console.error("THREE.WebGLRenderer: Maximum number of simultaneously usable uniforms groups reached."),0}function f(y){const x=i[y.id],v=y.uniforms,E=y.__cache;n.bindBuffer(n.UNIFORM_BUFFER,x);for(let _=0,A=v.length;_<A;_++){const k=Array.isArray(v[_])?v[_]:[v[_]];for(let w=0,M=k.length;w<M;w++){const R=k[w];if(b(R,_,w,E)===!0){const U=R.__offset,P=Array.isArray(R.value)?R.value:[R.value];let D=0;for(let V=0;V<P.length;V++){const B=P[V],G=g(B);typeof B=="number"||typeof B=="boolean"?(R.__data[0]=B,n.bufferSubData(n.UNIFORM_BUFFER,U+D,R.__data)):B.isMatrix3?(R.__data[0]=B.elements[0],R.__data[1]=B.elements[1],R.__data[2]=B.elements[2],R.__data[3]=0,R.__data[4]=B.elements[3],R.__data[5]=B.elements[4],R.__data[6]=B.elements[5],R.__data[7]=0,R.__data[8]=B.elements[6],R.__data[9]=B.elements[7],R.__data[10]=B.elements[8],R.__data[11]=0):(B.toArray(R.__data,D),D+=G.storage/Float32Array.BYTES_PER_ELEMENT)}n.bufferSubData(n.UNIFORM_BUFFER,U,R.__data)}}}n.bindBuffer(n.UNIFORM_BUFFER,null)}function b(y,x,v,E){const _=y.value,A=x+"_"+v;if(E[A]===void 0)return typeof _=="number"||typeof _=="boolean"?E[A]=_:E[A]=_.clone(),!0;{const k=E[A];if(typeof _=="number"||typeof _=="boolean"){if(k!==_)return E[A]=_,!0}else if(k.equals(_)===!1)return k.copy(_),!0}return!1}function p(y){const x=y.uniforms;let v=0;const E=16;for(let A=0,k=x.length;A<k;A++){const w=Array.isArray(x[A])?x[A]:[x[A]];for(let M=0,R=w.length;M<R;M++){const U=w[M],P=Array.isArray(U.value)?U.value:[U.value];for(let D=0,V=P.length;D<V;D++){const B=P[D],G=g(B),z=v%E,Y=z%G.boundary,te=z+Y;v+=Y,te!==0&&E-te<G.storage&&(v+=E-te),U.__data=new Float32Array(G.storage/Float32Array.BYTES_PER_ELEMENT),U.__offset=v,v+=G.storage}}}const _=v%E;return _>0&&(v+=E-_),y.__size=v,y.__cache={},this}function g(y){const x={boundary:0,storage:0};return typeof y=="number"||typeof y=="boolean"?(x.boundary=4,x.storage=4):y.isVector2?(x.boundary=8,x.storage=8):y.isVector3||y.isColor?(x.boundary=16,x.storage=12):y.isVector4?(x.boundary=16,x.storage=16):y.isMatrix3?(x.boundary=48,x.storage=48):y.isMatrix4?(x.boundary=64,x.storage=64):y.isTexture?console.warn("THREE.WebGLRenderer: Texture samplers can not be part of an uniforms group."):console.warn("THREE.WebGLRenderer: Unsupported uniform value type.",y),x}function m(y){const x=y.target;x.removeEventListener("dispose",m);const v=s.indexOf(x.__bindingPointIndex);s.splice(v,1),n.deleteBuffer(i[x.id]),delete i[x.id],delete r[x.id]}function u(){for(const y in i)n.deleteBuffer(i[y]);s=[],i={},r={}}return{bind:c,update:l,dispose:u}}class Ey{constructor(e={}){const{canvas:t=fb(),context:a=null,depth:i=!0,stencil:r=!1,alpha:s=!1,antialias:o=!1,premultipliedAlpha:c=!0,preserveDrawingBuffer:l=!1,powerPreference:h="default",failIfMajorPerformanceCaveat:d=!1,reverseDepthBuffer:f=!1}=e;this.isWebGLRenderer=!0;let b;if(a!==null){if(typeof WebGLRenderingContext<"u"&&a instanceof WebGLRenderingContext)throw new Error("THREE.WebGLRenderer: WebGL 1 is not supported since r163.");b=a.getContextAttributes().alpha}else b=s;const p=new Uint32Array(4),g=new Int32Array(4);let m=null,u=null;const y=[],x=[];this.domElement=t,this.debug={checkShaderErrors:!0,onShaderError:null},this.autoClear=!0,this.autoClearColor=!0,this.autoClearDepth=!0,this.autoClearStencil=!0,this.sortObjects=!0,this.clippingPlanes=[],this.localClippingEnabled=!1,this._outputColorSpace=kt,this.toneMapping=Ha,this.toneMappingExposure=1;const v=this;let E=!1,_=0,A=0,k=null,w=-1,M=null;const R=new ot,U=new ot;let P=null;const D=new Ve(0);let V=0,B=t.width,G=t.height,z=1,Y=null,te=null;const ie=new ot(0,0,B,G),pe=new ot(0,0,B,G);let Te=!1;const W=new rd;let J=!1,se=!1;const re=new ze,ge=new ze,Ae=new O,Re=new ot,We={background:null,fog:null,environment:null,overrideMaterial:null,isScene:!0};let Ie=!1;function Ke(){return k===null?z:1}let F=a;function vt(T,L){return t.getContext(T,L)}try{const T={alpha:!0,depth:i,stencil:r,antialias:o,premultipliedAlpha:c,preserveDrawingBuffer:l,powerPreference:h,failIfMajorPerformanceCaveat:d};if("setAttribute"in t&&t.setAttribute("data-engine",`three.js r${Po}`),t.addEventListener("webglcontextlost",$,!1),t.addEventListener("webglcontextrestored",fe,!1),t.addEventListener("webglcontextcreationerror",le,!1),F===null){const L="webgl2";if(F=vt(L,T),F===null)throw vt(L)?new Error("Error creating WebGL context with your selected attributes."):new Error("Error creating WebGL context.")}}catch(T){throw console.error("THREE.WebGLRenderer: "+T.message),T}let je,Oe,Ee,Ze,_e,C,S,H,Q,ee,Z,ve,ce,be,Ge,ae,me,Se,ke,ue,He,Fe,at,N;function he(){je=new Rg(F),je.init(),Fe=new by(F,je),Oe=new _g(F,je,e,Fe),Ee=new dy(F,je),Oe.reverseDepthBuffer&&f&&Ee.buffers.depth.setReversed(!0),Ze=new Pg(F),_e=new Yv,C=new uy(F,je,Ee,_e,Oe,Fe,Ze),S=new Sg(v),H=new kg(v),Q=new Ob(F),at=new wg(F,Q),ee=new Cg(F,Q,Ze,at),Z=new Ng(F,ee,Q,Ze),ke=new Dg(F,Oe,C),ae=new Eg(_e),ve=new Jv(v,S,H,je,Oe,at,ae),ce=new My(v,_e),be=new Qv,Ge=new iy(je),Se=new xg(v,S,H,Ee,Z,b,c),me=new hy(v,Z,Oe),N=new _y(F,Ze,Oe,Ee),ue=new Mg(F,je,Ze),He=new Ig(F,je,Ze),Ze.programs=ve.programs,v.capabilities=Oe,v.extensions=je,v.properties=_e,v.renderLists=be,v.shadowMap=me,v.state=Ee,v.info=Ze}he();const K=new xy(v,F);this.xr=K,this.getContext=function(){return F},this.getContextAttributes=function(){return F.getContextAttributes()},this.forceContextLoss=function(){const T=je.get("WEBGL_lose_context");T&&T.loseContext()},this.forceContextRestore=function(){const T=je.get("WEBGL_lose_context");T&&T.restoreContext()},this.getPixelRatio=function(){return z},this.setPixelRatio=function(T){T!==void 0&&(z=T,this.setSize(B,G,!1))},this.getSize=function(T){return T.set(B,G)},this.setSize=function(T,L,q=!0){if(K.isPresenting){console.warn("THREE.WebGLRenderer: Can't change size while VR device is presenting.");return}B=T,G=L,t.width=Math.floor(T*z),t.height=Math.floor(L*z),q===!0&&(t.style.width=T+"px",t.style.height=L+"px"),this.setViewport(0,0,T,L)},this.getDrawingBufferSize=function(T){return T.set(B*z,G*z).floor()},this.setDrawingBufferSize=function(T,L,q){B=T,G=L,z=q,t.width=Math.floor(T*q),t.height=Math.floor(L*q),this.setViewport(0,0,T,L)},this.getCurrentViewport=function(T){return T.copy(R)},this.getViewport=function(T){return T.copy(ie)},this.setViewport=function(T,L,q,X){T.isVector4?ie.set(T.x,T.y,T.z,T.w):ie.set(T,L,q,X),Ee.viewport(R.copy(ie).multiplyScalar(z).round())},this.getScissor=function(T){return T.copy(pe)},this.setScissor=function(T,L,q,X){T.isVector4?pe.set(T.x,T.y,T.z,T.w):pe.set(T,L,q,X),Ee.scissor(U.copy(pe).multiplyScalar(z).round())},this.getScissorTest=function(){return Te},this.setScissorTest=function(T){Ee.setScissorTest(Te=T)},this.setOpaqueSort=function(T){Y=T},this.setTransparentSort=function(T){te=T},this.getClearColor=function(T){return T.copy(Se.getClearColor())},this.setClearColor=function(){Se.setClearColor.apply(Se,arguments)},this.getClearAlpha=function(){return Se.getClearAlpha()},this.setClearAlpha=function(){Se.setClearAlpha.apply(Se,arguments)},this.clear=function(T=!0,L=!0,q=!0){let X=0;if(T){let j=!1;if(k!==null){const ne=k.texture.format;j=ne===jo||ne===Lo||ne===Fo}if(j){const ne=k.texture.type,de=ne===_a||ne===sn||ne===vi||ne===jn||ne===No||ne===Uo,ye=Se.getClearColor(),xe=Se.getClearAlpha(),Ce=ye.r,Ue=ye.g,we=ye.b;de?(p[0]=Ce,p[1]=Ue,p[2]=we,p[3]=xe,F.clearBufferuiv(F.COLOR,0,p)):(g[0]=Ce,g[1]=Ue,g[2]=we,g[3]=xe,F.clearBufferiv(F.COLOR,0,g))}else X|=F.COLOR_BUFFER_BIT}L&&(X|=F.DEPTH_BUFFER_BIT),q&&(X|=F.STENCIL_BUFFER_BIT,this.state.buffers.stencil.setMask(4294967295)),F.clear(X)},this.clearColor=function(){this.clear(!0,!1,!1)},this.clearDepth=function(){this.clear(!1,!0,!1)},this.clearStencil=function(){this.clear(!1,!1,!0)},this.dispose=function(){t.removeEventListener("webglcontextlost",$,!1),t.removeEventListener("webglcontextrestored",fe,!1),t.removeEventListener("webglcontextcreationerror",le,!1),be.dispose(),Ge.dispose(),_e.dispose(),S.dispose(),H.dispose(),Z.dispose(),at.dispose(),N.dispose(),ve.dispose(),K.dispose(),K.removeEventListener("sessionstart",ac),K.removeEventListener("sessionend",nc),qa.stop()};function $(T){T.preventDefault(),console.log("THREE.WebGLRenderer: Context Lost."),E=!0}function fe(){console.log("THREE.WebGLRenderer: Context Restored."),E=!1;const T=Ze.autoReset,L=me.enabled,q=me.autoUpdate,X=me.needsUpdate,j=me.type;he(),Ze.autoReset=T,me.enabled=L,me.autoUpdate=q,me.needsUpdate=X,me.type=j}function le(T){console.error("THREE.WebGLRenderer: A WebGL context could not be created. Reason: ",T.statusMessage)}function Ne(T){const L=T.target;L.removeEventListener("dispose",Ne),ct(L)}function ct(T){yt(T),_e.remove(T)}function yt(T){const L=_e.get(T).programs;L!==void 0&&(L.forEach(function(q){ve.releaseProgram(q)}),T.isShaderMaterial&&ve.releaseShaderCache(T))}this.renderBufferDirect=function(T,L,q,X,j,ne){L===null&&(L=We);const de=j.isMesh&&j.matrixWorld.determinant()<0,ye=af(T,L,q,X,j);Ee.setMaterial(X,de);let xe=q.index,Ce=1;if(X.wireframe===!0){if(xe=ee.getWireframeAttribute(q),xe===void 0)return;Ce=2}const Ue=q.drawRange,we=q.attributes.position;let Xe=Ue.start*Ce,nt=(Ue.start+Ue.count)*Ce;ne!==null&&(Xe=Math.max(Xe,ne.start*Ce),nt=Math.min(nt,(ne.start+ne.count)*Ce)),xe!==null?(Xe=Math.max(Xe,0),nt=Math.min(nt,xe.count)):we!=null&&(Xe=Math.max(Xe,0),nt=Math.min(nt,we.count));const it=nt-Xe;if(it<0||it===1/0)return;at.setup(j,X,ye,q,xe);let Ct,Je=ue;if(xe!==null&&(Ct=Q.get(xe),Je=He,Je.setIndex(Ct)),j.isMesh)X.wireframe===!0?(Ee.setLineWidth(X.wireframeLinewidth*Ke()),Je.setMode(F.LINES)):Je.setMode(F.TRIANGLES);else if(j.isLine){let Me=X.linewidth;Me===void 0&&(Me=1),Ee.setLineWidth(Me*Ke()),j.isLineSegments?Je.setMode(F.LINES):j.isLineLoop?Je.setMode(F.LINE_LOOP):Je.setMode(F.LINE_STRIP)}else j.isPoints?Je.setMode(F.POINTS):j.isSprite&&Je.setMode(F.TRIANGLES);if(j.isBatchedMesh)if(j._multiDrawInstances!==null)Je.renderMultiDrawInstances(j._multiDrawStarts,j._multiDrawCounts,j._multiDrawCount,j._multiDrawInstances);else if(je.get("WEBGL_multi_draw"))Je.renderMultiDraw(j._multiDrawStarts,j._multiDrawCounts,j._multiDrawCount);else{const Me=j._multiDrawStarts,ha=j._multiDrawCounts,Ye=j._multiDrawCount,Zt=xe?Q.get(xe).bytesPerElement:1,fn=_e.get(X).currentProgram.getUniforms();for(let Ft=0;Ft<Ye;Ft++)fn.setValue(F,"_gl_DrawID",Ft),Je.render(Me[Ft]/Zt,ha[Ft])}else if(j.isInstancedMesh)Je.renderInstances(Xe,it,j.count);else if(q.isInstancedBufferGeometry){const Me=q._maxInstanceCount!==void 0?q._maxInstanceCount:1/0,ha=Math.min(q.instanceCount,Me);Je.renderInstances(Xe,it,ha)}else Je.render(Xe,it)};function Qe(T,L,q){T.transparent===!0&&T.side===Kt&&T.forceSinglePass===!1?(T.side=Ut,T.needsUpdate=!0,Ci(T,L,q),T.side=Ma,T.needsUpdate=!0,Ci(T,L,q),T.side=Kt):Ci(T,L,q)}this.compile=function(T,L,q=null){q===null&&(q=T),u=Ge.get(q),u.init(L),x.push(u),q.traverseVisible(function(j){j.isLight&&j.layers.test(L.layers)&&(u.pushLight(j),j.castShadow&&u.pushShadow(j))}),T!==q&&T.traverseVisible(function(j){j.isLight&&j.layers.test(L.layers)&&(u.pushLight(j),j.castShadow&&u.pushShadow(j))}),u.setupLights();const X=new Set;return T.traverse(function(j){if(!(j.isMesh||j.isPoints||j.isLine||j.isSprite))return;const ne=j.material;if(ne)if(Array.isArray(ne))for(let de=0;de<ne.length;de++){const ye=ne[de];Qe(ye,q,j),X.add(ye)}else Qe(ne,q,j),X.add(ne)}),x.pop(),u=null,X},this.compileAsync=function(T,L,q=null){const X=this.compile(T,L,q);return new Promise(j=>{function ne(){if(X.forEach(function(de){_e.get(de).currentProgram.isReady()&&X.delete(de)}),X.size===0){j(T);return}setTimeout(ne,10)}je.get("KHR_parallel_shader_compile")!==null?ne():setTimeout(ne,10)})};let Yt=null;function ca(T){Yt&&Yt(T)}function ac(){qa.stop()}function nc(){qa.start()}const qa=new sd;qa.setAnimationLoop(ca),typeof self<"u"&&qa.setContext(self),this.setAnimationLoop=function(T){Yt=T,K.setAnimationLoop(T),T===null?qa.stop():qa.start()},K.addEventListener("sessionstart",ac),K.addEventListener("sessionend",nc),this.render=function(T,L){if(L!==void 0&&L.isCamera!==!0){console.error("THREE.WebGLRenderer.render: camera is not an instance of THREE.Camera.");return}if(E===!0)return;if(T.matrixWorldAutoUpdate===!0&&T.updateMatrixWorld(),L.parent===null&&L.matrixWorldAutoUpdate===!0&&L.updateMatrixWorld(),K.enabled===!0&&K.isPresenting===!0&&(K.cameraAutoUpdate===!0&&K.updateCamera(L),L=K.getCamera()),T.isScene===!0&&T.onBeforeRender(v,T,L,k),u=Ge.get(T,x.length),u.init(L),x.push(u),ge.multiplyMatrices(L.projectionMatrix,L.matrixWorldInverse),W.setFromProjectionMatrix(ge),se=this.localClippingEnabled,J=ae.init(this.clippingPlanes,se),m=be.get(T,y.length),m.init(),y.push(m),K.enabled===!0&&K.isPresenting===!0){const ne=v.xr.getDepthSensingMesh();ne!==null&&Ur(ne,L,-1/0,v.sortObjects)}Ur(T,L,0,v.sortObjects),m.finish(),v.sortObjects===!0&&m.sort(Y,te),Ie=K.enabled===!1||K.isPresenting===!1||K.hasDepthSensing()===!1,Ie&&Se.addToRenderList(m,T),this.info.render.frame++,J===!0&&ae.beginShadows();const q=u.state.shadowsArray;me.render(q,T,L),J===!0&&ae.endShadows(),this.info.autoReset===!0&&this.info.reset();const X=m.opaque,j=m.transmissive;if(u.setupLights(),L.isArrayCamera){const ne=L.cameras;if(j.length>0)for(let de=0,ye=ne.length;de<ye;de++){const xe=ne[de];rc(X,j,T,xe)}Ie&&Se.render(T);for(let de=0,ye=ne.length;de<ye;de++){const xe=ne[de];ic(m,T,xe,xe.viewport)}}else j.length>0&&rc(X,j,T,L),Ie&&Se.render(T),ic(m,T,L);k!==null&&(C.updateMultisampleRenderTarget(k),C.updateRenderTargetMipmap(k)),T.isScene===!0&&T.onAfterRender(v,T,L),at.resetDefaultState(),w=-1,M=null,x.pop(),x.length>0?(u=x[x.length-1],J===!0&&ae.setGlobalState(v.clippingPlanes,u.state.camera)):u=null,y.pop(),y.length>0?m=y[y.length-1]:m=null};function Ur(T,L,q,X){if(T.visible===!1)return;if(T.layers.test(L.layers)){if(T.isGroup)q=T.renderOrder;else if(T.isLOD)T.autoUpdate===!0&&T.update(L);else if(T.isLight)u.pushLight(T),T.castShadow&&u.pushShadow(T);else if(T.isSprite){if(!T.frustumCulled||W.intersectsSprite(T)){X&&Re.setFromMatrixPosition(T.matrixWorld).applyMatrix4(ge);const de=Z.update(T),ye=T.material;ye.visible&&m.push(T,de,ye,q,Re.z,null)}}else if((T.isMesh||T.isLine||T.isPoints)&&(!T.frustumCulled||W.intersectsObject(T))){const de=Z.update(T),ye=T.material;if(X&&(T.boundingSphere!==void 0?(T.boundingSphere===null&&T.computeBoundingSphere(),Re.copy(T.boundingSphere.center)):(de.boundingSphere===null&&de.computeBoundingSphere(),Re.copy(de.boundingSphere.center)),Re.applyMatrix4(T.matrixWorld).applyMatrix4(ge)),Array.isArray(ye)){const xe=de.groups;for(let Ce=0,Ue=xe.length;Ce<Ue;Ce++){const we=xe[Ce],Xe=ye[we.materialIndex];Xe&&Xe.visible&&m.push(T,de,Xe,q,Re.z,we)}}else ye.visible&&m.push(T,de,ye,q,Re.z,null)}}const ne=T.children;for(let de=0,ye=ne.length;de<ye;de++)Ur(ne[de],L,q,X)}function ic(T,L,q,X){const j=T.opaque,ne=T.transmissive,de=T.transparent;u.setupLightsView(q),J===!0&&ae.setGlobalState(v.clippingPlanes,q),X&&Ee.viewport(R.copy(X)),j.length>0&&Ri(j,L,q),ne.length>0&&Ri(ne,L,q),de.length>0&&Ri(de,L,q),Ee.buffers.depth.setTest(!0),Ee.buffers.depth.setMask(!0),Ee.buffers.color.setMask(!0),Ee.setPolygonOffset(!1)}function rc(T,L,q,X){if((q.isScene===!0?q.overrideMaterial:null)!==null)return;u.state.transmissionRenderTarget[X.id]===void 0&&(u.state.transmissionRenderTarget[X.id]=new Sa(1,1,{generateMipmaps:!0,type:je.has("EXT_color_buffer_half_float")||je.has("EXT_color_buffer_float")?Si:_a,minFilter:Ba,samples:4,stencilBuffer:r,resolveDepthBuffer:!1,resolveStencilBuffer:!1,colorSpace:qe.workingColorSpace}));const ne=u.state.transmissionRenderTarget[X.id],de=X.viewport||R;ne.setSize(de.z,de.w);const ye=v.getRenderTarget();v.setRenderTarget(ne),v.getClearColor(D),V=v.getClearAlpha(),V<1&&v.setClearColor(16777215,.5),v.clear(),Ie&&Se.render(q);const xe=v.toneMapping;v.toneMapping=Ha;const Ce=X.viewport;if(X.viewport!==void 0&&(X.viewport=void 0),u.setupLightsView(X),J===!0&&ae.setGlobalState(v.clippingPlanes,X),Ri(T,q,X),C.updateMultisampleRenderTarget(ne),C.updateRenderTargetMipmap(ne),je.has("WEBGL_multisampled_render_to_texture")===!1){let Ue=!1;for(let we=0,Xe=L.length;we<Xe;we++){const nt=L[we],it=nt.object,Ct=nt.geometry,Je=nt.material,Me=nt.group;if(Je.side===Kt&&it.layers.test(X.layers)){const ha=Je.side;Je.side=Ut,Je.needsUpdate=!0,sc(it,q,X,Ct,Je,Me),Je.side=ha,Je.needsUpdate=!0,Ue=!0}}Ue===!0&&(C.updateMultisampleRenderTarget(ne),C.updateRenderTargetMipmap(ne))}v.setRenderTarget(ye),v.setClearColor(D,V),Ce!==void 0&&(X.viewport=Ce),v.toneMapping=xe}function Ri(T,L,q){const X=L.isScene===!0?L.overrideMaterial:null;for(let j=0,ne=T.length;j<ne;j++){const de=T[j],ye=de.object,xe=de.geometry,Ce=X===null?de.material:X,Ue=de.group;ye.layers.test(q.layers)&&sc(ye,L,q,xe,Ce,Ue)}}function sc(T,L,q,X,j,ne){T.onBeforeRender(v,L,q,X,j,ne),T.modelViewMatrix.multiplyMatrices(q.matrixWorldInverse,T.matrixWorld),T.normalMatrix.getNormalMatrix(T.modelViewMatrix),j.onBeforeRender(v,L,q,X,T,ne),j.transparent===!0&&j.side===Kt&&j.forceSinglePass===!1?(j.side=Ut,j.needsUpdate=!0,v.renderBufferDirect(q,L,X,j,T,ne),j.side=Ma,j.needsUpdate=!0,v.renderBufferDirect(q,L,X,j,T,ne),j.side=Kt):v.renderBufferDirect(q,L,X,j,T,ne),T.onAfterRender(v,L,q,X,j,ne)}function Ci(T,L,q){L.isScene!==!0&&(L=We);const X=_e.get(T),j=u.state.lights,ne=u.state.shadowsArray,de=j.state.version,ye=ve.getParameters(T,j.state,ne,L,q),xe=ve.getProgramCacheKey(ye);let Ce=X.programs;X.environment=T.isMeshStandardMaterial?L.environment:null,X.fog=L.fog,X.envMap=(T.isMeshStandardMaterial?H:S).get(T.envMap||X.environment),X.envMapRotation=X.environment!==null&&T.envMap===null?L.environmentRotation:T.envMapRotation,Ce===void 0&&(T.addEventListener("dispose",Ne),Ce=new Map,X.programs=Ce);let Ue=Ce.get(xe);if(Ue!==void 0){if(X.currentProgram===Ue&&X.lightsStateVersion===de)return cc(T,ye),Ue}else ye.uniforms=ve.getUniforms(T),T.onBeforeCompile(ye,v),Ue=ve.acquireProgram(ye,xe),Ce.set(xe,Ue),X.uniforms=ye.uniforms;const we=X.uniforms;return(!T.isShaderMaterial&&!T.isRawShaderMaterial||T.clipping===!0)&&(we.clippingPlanes=ae.uniform),cc(T,ye),X.needsLights=rf(T),X.lightsStateVersion=de,X.needsLights&&(we.ambientLightColor.value=j.state.ambient,we.lightProbe.value=j.state.probe,we.directionalLights.value=j.state.directional,we.directionalLightShadows.value=j.state.directionalShadow,we.spotLights.value=j.state.spot,we.spotLightShadows.value=j.state.spotShadow,we.rectAreaLights.value=j.state.rectArea,we.ltc_1.value=j.state.rectAreaLTC1,we.ltc_2.value=j.state.rectAreaLTC2,we.pointLights.value=j.state.point,we.pointLightShadows.value=j.state.pointShadow,we.hemisphereLights.value=j.state.hemi,we.directionalShadowMap.value=j.state.directionalShadowMap,we.directionalShadowMatrix.value=j.state.directionalShadowMatrix,we.spotShadowMap.value=j.state.spotShadowMap,we.spotLightMatrix.value=j.state.spotLightMatrix,we.spotLightMap.value=j.state.spotLightMap,we.pointShadowMap.value=j.state.pointShadowMap,we.pointShadowMatrix.value=j.state.pointShadowMatrix),X.currentProgram=Ue,X.uniformsList=null,Ue}function oc(T){if(T.uniformsList===null){const L=T.currentProgram.getUniforms();T.uniformsList=dr.seqWithValue(L.seq,T.uniforms)}return T.uniformsList}function cc(T,L){const q=_e.get(T);q.outputColorSpace=L.outputColorSpace,q.batching=L.batching,q.batchingColor=L.batchingColor,q.instancing=L.instancing,q.instancingColor=L.instancingColor,q.instancingMorph=L.instancingMorph,q.skinning=L.skinning,q.morphTargets=L.morphTargets,q.morphNormals=L.morphNormals,q.morphColors=L.morphColors,q.morphTargetsCount=L.morphTargetsCount,q.numClippingPlanes=L.numClippingPlanes,q.numIntersection=L.numClipIntersection,q.vertexAlphas=L.vertexAlphas,q.vertexTangents=L.vertexTangents,q.toneMapping=L.toneMapping}function af(T,L,q,X,j){L.isScene!==!0&&(L=We),C.resetTextureUnits();const ne=L.fog,de=X.isMeshStandardMaterial?L.environment:null,ye=k===null?v.outputColorSpace:k.isXRRenderTarget===!0?k.texture.colorSpace:Hn,xe=(X.isMeshStandardMaterial?H:S).get(X.envMap||de),Ce=X.vertexColors===!0&&!!q.attributes.color&&q.attributes.color.itemSize===4,Ue=!!q.attributes.tangent&&(!!X.normalMap||X.anisotropy>0),we=!!q.morphAttributes.position,Xe=!!q.morphAttributes.normal,nt=!!q.morphAttributes.color;let it=Ha;X.toneMapped&&(k===null||k.isXRRenderTarget===!0)&&(it=v.toneMapping);const Ct=q.morphAttributes.position||q.morphAttributes.normal||q.morphAttributes.color,Je=Ct!==void 0?Ct.length:0,Me=_e.get(X),ha=u.state.lights;if(J===!0&&(se===!0||T!==M)){const Gt=T===M&&X.id===w;ae.setState(X,T,Gt)}let Ye=!1;X.version===Me.__version?(Me.needsLights&&Me.lightsStateVersion!==ha.state.version||Me.outputColorSpace!==ye||j.isBatchedMesh&&Me.batching===!1||!j.isBatchedMesh&&Me.batching===!0||j.isBatchedMesh&&Me.batchingColor===!0&&j.colorTexture===null||j.isBatchedMesh&&Me.batchingColor===!1&&j.colorTexture!==null||j.isInstancedMesh&&Me.instancing===!1||!j.isInstancedMesh&&Me.instancing===!0||j.isSkinnedMesh&&Me.skinning===!1||!j.isSkinnedMesh&&Me.skinning===!0||j.isInstancedMesh&&Me.instancingColor===!0&&j.instanceColor===null||j.isInstancedMesh&&Me.instancingColor===!1&&j.instanceColor!==null||j.isInstancedMesh&&Me.instancingMorph===!0&&j.morphTexture===null||j.isInstancedMesh&&Me.instancingMorph===!1&&j.morphTexture!==null||Me.envMap!==xe||X.fog===!0&&Me.fog!==ne||Me.numClippingPlanes!==void 0&&(Me.numClippingPlanes!==ae.numPlanes||Me.numIntersection!==ae.numIntersection)||Me.vertexAlphas!==Ce||Me.vertexTangents!==Ue||Me.morphTargets!==we||Me.morphNormals!==Xe||Me.morphColors!==nt||Me.toneMapping!==it||Me.morphTargetsCount!==Je)&&(Ye=!0):(Ye=!0,Me.__version=X.version);let Zt=Me.currentProgram;Ye===!0&&(Zt=Ci(X,L,j));let fn=!1,Ft=!1,Xn=!1;const rt=Zt.getUniforms(),ra=Me.uniforms;if(Ee.useProgram(Zt.program)&&(fn=!0,Ft=!0,Xn=!0),X.id!==w&&(w=X.id,Ft=!0),fn||M!==T){Ee.buffers.depth.getReversed()?(re.copy(T.projectionMatrix),bb(re),mb(re),rt.setValue(F,"projectionMatrix",re)):rt.setValue(F,"projectionMatrix",T.projectionMatrix),rt.setValue(F,"viewMatrix",T.matrixWorldInverse);const ka=rt.map.cameraPosition;ka!==void 0&&ka.setValue(F,Ae.setFromMatrixPosition(T.matrixWorld)),Oe.logarithmicDepthBuffer&&rt.setValue(F,"logDepthBufFC",2/(Math.log(T.far+1)/Math.LN2)),(X.isMeshPhongMaterial||X.isMeshToonMaterial||X.isMeshLambertMaterial||X.isMeshBasicMaterial||X.isMeshStandardMaterial||X.isShaderMaterial)&&rt.setValue(F,"isOrthographic",T.isOrthographicCamera===!0),M!==T&&(M=T,Ft=!0,Xn=!0)}if(j.isSkinnedMesh){rt.setOptional(F,j,"bindMatrix"),rt.setOptional(F,j,"bindMatrixInverse");const Gt=j.skeleton;Gt&&(Gt.boneTexture===null&&Gt.computeBoneTexture(),rt.setValue(F,"boneTexture",Gt.boneTexture,C))}j.isBatchedMesh&&(rt.setOptional(F,j,"batchingTexture"),rt.setValue(F,"batchingTexture",j._matricesTexture,C),rt.setOptional(F,j,"batchingIdTexture"),rt.setValue(F,"batchingIdTexture",j._indirectTexture,C),rt.setOptional(F,j,"batchingColorTexture"),j._colorsTexture!==null&&rt.setValue(F,"batchingColorTexture",j._colorsTexture,C));const Kn=q.morphAttributes;if((Kn.position!==void 0||Kn.normal!==void 0||Kn.color!==void 0)&&ke.update(j,q,Zt),(Ft||Me.receiveShadow!==j.receiveShadow)&&(Me.receiveShadow=j.receiveShadow,rt.setValue(F,"receiveShadow",j.receiveShadow)),X.isMeshGouraudMaterial&&X.envMap!==null&&(ra.envMap.value=xe,ra.flipEnvMap.value=xe.isCubeTexture&&xe.isRenderTargetTexture===!1?-1:1),X.isMeshStandardMaterial&&X.envMap===null&&L.environment!==null&&(ra.envMapIntensity.value=L.environmentIntensity),Ft&&(rt.setValue(F,"toneMappingExposure",v.toneMappingExposure),Me.needsLights&&nf(ra,Xn),ne&&X.fog===!0&&ce.refreshFogUniforms(ra,ne),ce.refreshMaterialUniforms(ra,X,z,G,u.state.transmissionRenderTarget[T.id]),dr.upload(F,oc(Me),ra,C)),X.isShaderMaterial&&X.uniformsNeedUpdate===!0&&(dr.upload(F,oc(Me),ra,C),X.uniformsNeedUpdate=!1),X.isSpriteMaterial&&rt.setValue(F,"center",j.center),rt.setValue(F,"modelViewMatrix",j.modelViewMatrix),rt.setValue(F,"normalMatrix",j.normalMatrix),rt.setValue(F,"modelMatrix",j.matrixWorld),X.isShaderMaterial||X.isRawShaderMaterial){const Gt=X.uniformsGroups;for(let ka=0,Ra=Gt.length;ka<Ra;ka++){const hc=Gt[ka];N.update(hc,Zt),N.bind(hc,Zt)}}return Zt}function nf(T,L){T.ambientLightColor.needsUpdate=L,T.lightProbe.needsUpdate=L,T.directionalLights.needsUpdate=L,T.directionalLightShadows.needsUpdate=L,T.pointLights.needsUpdate=L,T.pointLightShadows.needsUpdate=L,T.spotLights.needsUpdate=L,T.spotLightShadows.needsUpdate=L,T.rectAreaLights.needsUpdate=L,T.hemisphereLights.needsUpdate=L}function rf(T){return T.isMeshLambertMaterial||T.isMeshToonMaterial||T.isMeshPhongMaterial||T.isMeshStandardMaterial||T.isShadowMaterial||T.isShaderMaterial&&T.lights===!0}this.getActiveCubeFace=function(){return _},this.getActiveMipmapLevel=function(){return A},this.getRenderTarget=function(){return k},this.setRenderTargetTextures=function(T,L,q){_e.get(T.texture).__webglTexture=L,_e.get(T.depthTexture).__webglTexture=q;const X=_e.get(T);X.__hasExternalTextures=!0,X.__autoAllocateDepthBuffer=q===void 0,X.__autoAllocateDepthBuffer||je.has("WEBGL_multisampled_render_to_texture")===!0&&(console.warn("THREE.WebGLRenderer: Render-to-texture extension was disabled because an external texture was provided"),X.__useRenderToTexture=!1)},this.setRenderTargetFramebuffer=function(T,L){const q=_e.get(T);q.__webglFramebuffer=L,q.__useDefaultFramebuffer=L===void 0},this.setRenderTarget=function(T,L=0,q=0){k=T,_=L,A=q;let X=!0,j=null,ne=!1,de=!1;if(T){const xe=_e.get(T);if(xe.__useDefaultFramebuffer!==void 0)Ee.bindFramebuffer(F.FRAMEBUFFER,null),X=!1;else if(xe.__webglFramebuffer===void 0)C.setupRenderTarget(T);else if(xe.__hasExternalTextures)C.rebindTextures(T,_e.get(T.texture).__webglTexture,_e.get(T.depthTexture).__webglTexture);else if(T.depthBuffer){const we=T.depthTexture;if(xe.__boundDepthTexture!==we){if(we!==null&&_e.has(we)&&(T.width!==we.image.width||T.height!==we.image.height))throw new Error("WebGLRenderTarget: Attached DepthTexture is initialized to the incorrect size.");C.setupDepthRenderbuffer(T)}}const Ce=T.texture;(Ce.isData3DTexture||Ce.isDataArrayTexture||Ce.isCompressedArrayTexture)&&(de=!0);const Ue=_e.get(T).__webglFramebuffer;T.isWebGLCubeRenderTarget?(Array.isArray(Ue[L])?j=Ue[L][q]:j=Ue[L],ne=!0):T.samples>0&&C.useMultisampledRTT(T)===!1?j=_e.get(T).__webglMultisampledFramebuffer:Array.isArray(Ue)?j=Ue[q]:j=Ue,R.copy(T.viewport),U.copy(T.scissor),P=T.scissorTest}else R.copy(ie).multiplyScalar(z).floor(),U.copy(pe).multiplyScalar(z).floor(),P=Te;if(Ee.bindFramebuffer(F.FRAMEBUFFER,j)&&X&&Ee.drawBuffers(T,j),Ee.viewport(R),Ee.scissor(U),Ee.setScissorTest(P),ne){const xe=_e.get(T.texture);F.framebufferTexture2D(F.FRAMEBUFFER,F.COLOR_ATTACHMENT0,F.TEXTURE_CUBE_MAP_POSITIVE_X+L,xe.__webglTexture,q)}else if(de){const xe=_e.get(T.texture),Ce=L||0;F.framebufferTextureLayer(F.FRAMEBUFFER,F.COLOR_ATTACHMENT0,xe.__webglTexture,q||0,Ce)}w=-1},this.readRenderTargetPixels=function(T,L,q,X,j,ne,de){if(!(T&&T.isWebGLRenderTarget)){console.error("THREE.WebGLRenderer.readRenderTargetPixels: renderTarget is not THREE.WebGLRenderTarget.");return}let ye=_e.get(T).__webglFramebuffer;if(T.isWebGLCubeRenderTarget&&de!==void 0&&(ye=ye[de]),ye){Ee.bindFramebuffer(F.FRAMEBUFFER,ye);try{const xe=T.texture,Ce=xe.format,Ue=xe.type;if(!Oe.textureFormatReadable(Ce)){console.error("THREE.WebGLRenderer.readRenderTargetPixels: renderTarget is not in RGBA or implementation defined format.");return}if(!Oe.textureTypeReadable(Ue)){console.error("THREE.WebGLRenderer.readRenderTargetPixels: renderTarget is not in UnsignedByteType or implementation defined type.");return}L>=0&&L<=T.width-X&&q>=0&&q<=T.height-j&&F.readPixels(L,q,X,j,Fe.convert(Ce),Fe.convert(Ue),ne)}finally{const xe=k!==null?_e.get(k).__webglFramebuffer:null;Ee.bindFramebuffer(F.FRAMEBUFFER,xe)}}},this.readRenderTargetPixelsAsync=async function(T,L,q,X,j,ne,de){if(!(T&&T.isWebGLRenderTarget))throw new Error("THREE.WebGLRenderer.readRenderTargetPixels: renderTarget is not THREE.WebGLRenderTarget.");let ye=_e.get(T).__webglFramebuffer;if(T.isWebGLCubeRenderTarget&&de!==void 0&&(ye=ye[de]),ye){const xe=T.texture,Ce=xe.format,Ue=xe.type;if(!Oe.textureFormatReadable(Ce))throw new Error("THREE.WebGLRenderer.readRenderTargetPixelsAsync: renderTarget is not in RGBA or implementation defined format.");if(!Oe.textureTypeReadable(Ue))throw new Error("THREE.WebGLRenderer.readRenderTargetPixelsAsync: renderTarget is not in UnsignedByteType or implementation defined type.");if(L>=0&&L<=T.width-X&&q>=0&&q<=T.height-j){Ee.bindFramebuffer(F.FRAMEBUFFER,ye);const we=F.createBuffer();F.bindBuffer(F.PIXEL_PACK_BUFFER,we),F.bufferData(F.PIXEL_PACK_BUFFER,ne.byteLength,F.STREAM_READ),F.readPixels(L,q,X,j,Fe.convert(Ce),Fe.convert(Ue),0);const Xe=k!==null?_e.get(k).__webglFramebuffer:null;Ee.bindFramebuffer(F.FRAMEBUFFER,Xe);const nt=F.fenceSync(F.SYNC_GPU_COMMANDS_COMPLETE,0);return F.flush(),await ub(F,nt,4),F.bindBuffer(F.PIXEL_PACK_BUFFER,we),F.getBufferSubData(F.PIXEL_PACK_BUFFER,0,ne),F.deleteBuffer(we),F.deleteSync(nt),ne}else throw new Error("THREE.WebGLRenderer.readRenderTargetPixelsAsync: requested read bounds are out of range.")}},this.copyFramebufferToTexture=function(T,L=null,q=0){T.isTexture!==!0&&(hi("WebGLRenderer: copyFramebufferToTexture function signature has changed."),L=arguments[0]||null,T=arguments[1]);const X=Math.pow(2,-q),j=Math.floor(T.image.width*X),ne=Math.floor(T.image.height*X),de=L!==null?L.x:0,ye=L!==null?L.y:0;C.setTexture2D(T,0),F.copyTexSubImage2D(F.TEXTURE_2D,q,0,0,de,ye,j,ne),Ee.unbindTexture()},this.copyTextureToTexture=function(T,L,q=null,X=null,j=0){T.isTexture!==!0&&(hi("WebGLRenderer: copyTextureToTexture function signature has changed."),X=arguments[0]||null,T=arguments[1],L=arguments[2],j=arguments[3]||0,q=null);let ne,de,ye,xe,Ce,Ue,we,Xe,nt;const it=T.isCompressedTexture?T.mipmaps[j]:T.image;q!==null?(ne=q.max.x-q.min.x,de=q.max.y-q.min.y,ye=q.isBox3?q.max.z-q.min.z:1,xe=q.min.x,Ce=q.min.y,Ue=q.isBox3?q.min.z:0):(ne=it.width,de=it.height,ye=it.depth||1,xe=0,Ce=0,Ue=0),X!==null?(we=X.x,Xe=X.y,nt=X.z):(we=0,Xe=0,nt=0);const Ct=Fe.convert(L.format),Je=Fe.convert(L.type);let Me;L.isData3DTexture?(C.setTexture3D(L,0),Me=F.TEXTURE_3D):L.isDataArrayTexture||L.isCompressedArrayTexture?(C.setTexture2DArray(L,0),Me=F.TEXTURE_2D_ARRAY):(C.setTexture2D(L,0),Me=F.TEXTURE_2D),F.pixelStorei(F.UNPACK_FLIP_Y_WEBGL,L.flipY),F.pixelStorei(F.UNPACK_PREMULTIPLY_ALPHA_WEBGL,L.premultiplyAlpha),F.pixelStorei(F.UNPACK_ALIGNMENT,L.unpackAlignment);const ha=F.getParameter(F.UNPACK_ROW_LENGTH),Ye=F.getParameter(F.UNPACK_IMAGE_HEIGHT),Zt=F.getParameter(F.UNPACK_SKIP_PIXELS),fn=F.getParameter(F.UNPACK_SKIP_ROWS),Ft=F.getParameter(F.UNPACK_SKIP_IMAGES);F.pixelStorei(F.UNPACK_ROW_LENGTH,it.width),F.pixelStorei(F.UNPACK_IMAGE_HEIGHT,it.height),F.pixelStorei(F.UNPACK_SKIP_PIXELS,xe),F.pixelStorei(F.UNPACK_SKIP_ROWS,Ce),F.pixelStorei(F.UNPACK_SKIP_IMAGES,Ue);const Xn=T.isDataArrayTexture||T.isData3DTexture,rt=L.isDataArrayTexture||L.isData3DTexture;if(T.isRenderTargetTexture||T.isDepthTexture){const ra=_e.get(T),Kn=_e.get(L),Gt=_e.get(ra.__renderTarget),ka=_e.get(Kn.__renderTarget);Ee.bindFramebuffer(F.READ_FRAMEBUFFER,Gt.__webglFramebuffer),Ee.bindFramebuffer(F.DRAW_FRAMEBUFFER,ka.__webglFramebuffer);for(let Ra=0;Ra<ye;Ra++)Xn&&F.framebufferTextureLayer(F.READ_FRAMEBUFFER,F.COLOR_ATTACHMENT0,_e.get(T).__webglTexture,j,Ue+Ra),T.isDepthTexture?(rt&&F.framebufferTextureLayer(F.DRAW_FRAMEBUFFER,F.COLOR_ATTACHMENT0,_e.get(L).__webglTexture,j,nt+Ra),F.blitFramebuffer(xe,Ce,ne,de,we,Xe,ne,de,F.DEPTH_BUFFER_BIT,F.NEAREST)):rt?F.copyTexSubImage3D(Me,j,we,Xe,nt+Ra,xe,Ce,ne,de):F.copyTexSubImage2D(Me,j,we,Xe,nt+Ra,xe,Ce,ne,de);Ee.bindFramebuffer(F.READ_FRAMEBUFFER,null),Ee.bindFramebuffer(F.DRAW_FRAMEBUFFER,null)}else rt?T.isDataTexture||T.isData3DTexture?F.texSubImage3D(Me,j,we,Xe,nt,ne,de,ye,Ct,Je,it.data):L.isCompressedArrayTexture?F.compressedTexSubImage3D(Me,j,we,Xe,nt,ne,de,ye,Ct,it.data):F.texSubImage3D(Me,j,we,Xe,nt,ne,de,ye,Ct,Je,it):T.isDataTexture?F.texSubImage2D(F.TEXTURE_2D,j,we,Xe,ne,de,Ct,Je,it.data):T.isCompressedTexture?F.compressedTexSubImage2D(F.TEXTURE_2D,j,we,Xe,it.width,it.height,Ct,it.data):F.texSubImage2D(F.TEXTURE_2D,j,we,Xe,ne,de,Ct,Je,it);F.pixelStorei(F.UNPACK_ROW_LENGTH,ha),F.pixelStorei(F.UNPACK_IMAGE_HEIGHT,Ye),F.pixelStorei(F.UNPACK_SKIP_PIXELS,Zt),F.pixelStorei(F.UNPACK_SKIP_ROWS,fn),F.pixelStorei(F.UNPACK_SKIP_IMAGES,Ft),j===0&&L.generateMipmaps&&F.generateMipmap(Me),Ee.unbindTexture()},this.copyTextureToTexture3D=function(T,L,q=null,X=null,j=0){return T.isTexture!==!0&&(hi("WebGLRenderer: copyTextureToTexture3D function signature has changed."),q=arguments[0]||null,X=arguments[1]||null,T=arguments[2],L=arguments[3],j=arguments[4]||0),hi('WebGLRenderer: copyTextureToTexture3D function has been deprecated. Use "copyTextureToTexture" instead.'),this.copyTextureToTexture(T,L,q,X,j)},this.initRenderTarget=function(T){_e.get(T).__webglFramebuffer===void 0&&C.setupRenderTarget(T)},this.initTexture=function(T){T.isCubeTexture?C.setTextureCube(T,0):T.isData3DTexture?C.setTexture3D(T,0):T.isDataArrayTexture||T.isCompressedArrayTexture?C.setTexture2DArray(T,0):C.setTexture2D(T,0),Ee.unbindTexture()},this.resetState=function(){_=0,A=0,k=null,Ee.reset(),at.reset()},typeof __THREE_DEVTOOLS__<"u"&&__THREE_DEVTOOLS__.dispatchEvent(new CustomEvent("observe",{detail:this}))}get coordinateSystem(){return va}get outputColorSpace(){return this._outputColorSpace}set outputColorSpace(e){this._outputColorSpace=e;const t=this.getContext();t.drawingBufferColorspace=qe._getDrawingBufferColorSpace(e),t.unpackColorSpace=qe._getUnpackColorSpace()}}class Ho extends Et{constructor(){super(),this.isScene=!0,this.type="Scene",this.background=null,this.environment=null,this.fog=null,this.backgroundBlurriness=0,this.backgroundIntensity=1,this.backgroundRotation=new Aa,this.environmentIntensity=1,this.environmentRotation=new Aa,this.overrideMaterial=null,typeof __THREE_DEVTOOLS__<"u"&&__THREE_DEVTOOLS__.dispatchEvent(new CustomEvent("observe",{detail:this}))}copy(e,t){return super.copy(e,t),e.background!==null&&(this.background=e.background.clone()),e.environment!==null&&(this.environment=e.environment.clone()),e.fog!==null&&(this.fog=e.fog.clone()),this.backgroundBlurriness=e.backgroundBlurriness,this.backgroundIntensity=e.backgroundIntensity,this.backgroundRotation.copy(e.backgroundRotation),this.environmentIntensity=e.environmentIntensity,this.environmentRotation.copy(e.environmentRotation),e.overrideMaterial!==null&&(this.overrideMaterial=e.overrideMaterial.clone()),this.matrixAutoUpdate=e.matrixAutoUpdate,this}toJSON(e){const t=super.toJSON(e);return this.fog!==null&&(t.object.fog=this.fog.toJSON()),this.backgroundBlurriness>0&&(t.object.backgroundBlurriness=this.backgroundBlurriness),this.backgroundIntensity!==1&&(t.object.backgroundIntensity=this.backgroundIntensity),t.object.backgroundRotation=this.backgroundRotation.toArray(),this.environmentIntensity!==1&&(t.object.environmentIntensity=this.environmentIntensity),t.object.environmentRotation=this.environmentRotation.toArray(),t}}class yh{constructor(e,t){this.isInterleavedBuffer=!0,this.array=e,this.stride=t,this.count=e!==void 0?e.length/t:0,this.usage=po,this.updateRanges=[],this.version=0,this.uuid=oa()}onUploadCallback(){}set needsUpdate(e){e===!0&&this.version++}setUsage(e){return this.usage=e,this}addUpdateRange(e,t){this.updateRanges.push({start:e,count:t})}clearUpdateRanges(){this.updateRanges.length=0}copy(e){return this.array=new e.array.constructor(e.array),this.count=e.count,this.stride=e.stride,this.usage=e.usage,this}copyAt(e,t,a){e*=this.stride,a*=t.stride;for(let i=0,r=this.stride;i<r;i++)this.array[e+i]=t.array[a+i];return this}set(e,t=0){return this.array.set(e,t),this}clone(e){e.arrayBuffers===void 0&&(e.arrayBuffers={}),this.array.buffer._uuid===void 0&&(this.array.buffer._uuid=oa()),e.arrayBuffers[this.array.buffer._uuid]===void 0&&(e.arrayBuffers[this.array.buffer._uuid]=this.array.slice(0).buffer);const t=new this.array.constructor(e.arrayBuffers[this.array.buffer._uuid]),a=new this.constructor(t,this.stride);return a.setUsage(this.usage),a}onUpload(e){return this.onUploadCallback=e,this}toJSON(e){return e.arrayBuffers===void 0&&(e.arrayBuffers={}),this.array.buffer._uuid===void 0&&(this.array.buffer._uuid=oa()),e.arrayBuffers[this.array.buffer._uuid]===void 0&&(e.arrayBuffers[this.array.buffer._uuid]=Array.from(new Uint32Array(this.array.buffer))),{uuid:this.uuid,buffer:this.array.buffer._uuid,type:this.array.constructor.name,stride:this.stride}}}const At=new O;class Cn{constructor(e,t,a,i=!1){this.isInterleavedBufferAttribute=!0,this.name="",this.data=e,this.itemSize=t,this.offset=a,this.normalized=i}get count(){return this.data.count}get array(){return this.data.array}set needsUpdate(e){this.data.needsUpdate=e}applyMatrix4(e){for(let t=0,a=this.data.count;t<a;t++)At.fromBufferAttribute(this,t),At.applyMatrix4(e),this.setXYZ(t,At.x,At.y,At.z);return this}applyNormalMatrix(e){for(let t=0,a=this.count;t<a;t++)At.fromBufferAttribute(this,t),At.applyNormalMatrix(e),this.setXYZ(t,At.x,At.y,At.z);return this}transformDirection(e){for(let t=0,a=this.count;t<a;t++)At.fromBufferAttribute(this,t),At.transformDirection(e),this.setXYZ(t,At.x,At.y,At.z);return this}getComponent(e,t){let a=this.array[e*this.data.stride+this.offset+t];return this.normalized&&(a=ta(a,this.array)),a}setComponent(e,t,a){return this.normalized&&(a=$e(a,this.array)),this.data.array[e*this.data.stride+this.offset+t]=a,this}setX(e,t){return this.normalized&&(t=$e(t,this.array)),this.data.array[e*this.data.stride+this.offset]=t,this}setY(e,t){return this.normalized&&(t=$e(t,this.array)),this.data.array[e*this.data.stride+this.offset+1]=t,this}setZ(e,t){return this.normalized&&(t=$e(t,this.array)),this.data.array[e*this.data.stride+this.offset+2]=t,this}setW(e,t){return this.normalized&&(t=$e(t,this.array)),this.data.array[e*this.data.stride+this.offset+3]=t,this}getX(e){let t=this.data.array[e*this.data.stride+this.offset];return this.normalized&&(t=ta(t,this.array)),t}getY(e){let t=this.data.array[e*this.data.stride+this.offset+1];return this.normalized&&(t=ta(t,this.array)),t}getZ(e){let t=this.data.array[e*this.data.stride+this.offset+2];return this.normalized&&(t=ta(t,this.array)),t}getW(e){let t=this.data.array[e*this.data.stride+this.offset+3];return this.normalized&&(t=ta(t,this.array)),t}setXY(e,t,a){return e=e*this.data.stride+this.offset,this.normalized&&(t=$e(t,this.array),a=$e(a,this.array)),this.data.array[e+0]=t,this.data.array[e+1]=a,this}setXYZ(e,t,a,i){return e=e*this.data.stride+this.offset,this.normalized&&(t=$e(t,this.array),a=$e(a,this.array),i=$e(i,this.array)),this.data.array[e+0]=t,this.data.array[e+1]=a,this.data.array[e+2]=i,this}setXYZW(e,t,a,i,r){return e=e*this.data.stride+this.offset,this.normalized&&(t=$e(t,this.array),a=$e(a,this.array),i=$e(i,this.array),r=$e(r,this.array)),this.data.array[e+0]=t,this.data.array[e+1]=a,this.data.array[e+2]=i,this.data.array[e+3]=r,this}clone(e){if(e===void 0){console.log("THREE.InterleavedBufferAttribute.clone(): Cloning an interleaved buffer attribute will de-interleave buffer data.");const t=[];for(let a=0;a<this.count;a++){const i=a*this.data.stride+this.offset;for(let r=0;r<this.itemSize;r++)t.push(this.data.array[i+r])}return new Be(new this.array.constructor(t),this.itemSize,this.normalized)}else return e.interleavedBuffers===void 0&&(e.interleavedBuffers={}),e.interleavedBuffers[this.data.uuid]===void 0&&(e.interleavedBuffers[this.data.uuid]=this.data.clone(e)),new Cn(e.interleavedBuffers[this.data.uuid],this.itemSize,this.offset,this.normalized)}toJSON(e){if(e===void 0){console.log("THREE.InterleavedBufferAttribute.toJSON(): Serializing an interleaved buffer attribute will de-interleave buffer data.");const t=[];for(let a=0;a<this.count;a++){const i=a*this.data.stride+this.offset;for(let r=0;r<this.itemSize;r++)t.push(this.data.array[i+r])}return{itemSize:this.itemSize,type:this.array.constructor.name,array:t,normalized:this.normalized}}else return e.interleavedBuffers===void 0&&(e.interleavedBuffers={}),e.interleavedBuffers[this.data.uuid]===void 0&&(e.interleavedBuffers[this.data.uuid]=this.data.toJSON(e)),{isInterleavedBufferAttribute:!0,itemSize:this.itemSize,data:this.data.uuid,offset:this.offset,normalized:this.normalized}}}const xh=new O,wh=new ot,Mh=new ot,Sy=new O,_h=new ze,Zi=new O,fs=new dn,Eh=new ze,us=new Ai;class Sh extends Nt{constructor(e,t){super(e,t),this.isSkinnedMesh=!0,this.type="SkinnedMesh",this.bindMode=Sc,this.bindMatrix=new ze,this.bindMatrixInverse=new ze,this.boundingBox=null,this.boundingSphere=null}computeBoundingBox(){const e=this.geometry;this.boundingBox===null&&(this.boundingBox=new ln),this.boundingBox.makeEmpty();const t=e.getAttribute("position");for(let a=0;a<t.count;a++)this.getVertexPosition(a,Zi),this.boundingBox.expandByPoint(Zi)}computeBoundingSphere(){const e=this.geometry;this.boundingSphere===null&&(this.boundingSphere=new dn),this.boundingSphere.makeEmpty();const t=e.getAttribute("position");for(let a=0;a<t.count;a++)this.getVertexPosition(a,Zi),this.boundingSphere.expandByPoint(Zi)}copy(e,t){return super.copy(e,t),this.bindMode=e.bindMode,this.bindMatrix.copy(e.bindMatrix),this.bindMatrixInverse.copy(e.bindMatrixInverse),this.skeleton=e.skeleton,e.boundingBox!==null&&(this.boundingBox=e.boundingBox.clone()),e.boundingSphere!==null&&(this.boundingSphere=e.boundingSphere.clone()),this}raycast(e,t){const a=this.material,i=this.matrixWorld;a!==void 0&&(this.boundingSphere===null&&this.computeBoundingSphere(),fs.copy(this.boundingSphere),fs.applyMatrix4(i),e.ray.intersectsSphere(fs)!==!1&&(Eh.copy(i).invert(),us.copy(e.ray).applyMatrix4(Eh),!(this.boundingBox!==null&&us.intersectsBox(this.boundingBox)===!1)&&this._computeIntersections(e,t,us)))}getVertexPosition(e,t){return super.getVertexPosition(e,t),this.applyBoneTransform(e,t),t}bind(e,t){this.skeleton=e,t===void 0&&(this.updateMatrixWorld(!0),this.skeleton.calculateInverses(),t=this.matrixWorld),this.bindMatrix.copy(t),this.bindMatrixInverse.copy(t).invert()}pose(){this.skeleton.pose()}normalizeSkinWeights(){const e=new ot,t=this.geometry.attributes.skinWeight;for(let a=0,i=t.count;a<i;a++){e.fromBufferAttribute(t,a);const r=1/e.manhattanLength();r!==1/0?e.multiplyScalar(r):e.set(1,0,0,0),t.setXYZW(a,e.x,e.y,e.z,e.w)}}updateMatrixWorld(e){super.updateMatrixWorld(e),this.bindMode===Sc?this.bindMatrixInverse.copy(this.matrixWorld).invert():this.bindMode===zs?this.bindMatrixInverse.copy(this.bindMatrix).invert():console.warn("THREE.SkinnedMesh: Unrecognized bindMode: "+this.bindMode)}applyBoneTransform(e,t){const a=this.skeleton,i=this.geometry;wh.fromBufferAttribute(i.attributes.skinIndex,e),Mh.fromBufferAttribute(i.attributes.skinWeight,e),xh.copy(t).applyMatrix4(this.bindMatrix),t.set(0,0,0);for(let r=0;r<4;r++){const s=Mh.getComponent(r);if(s!==0){const o=wh.getComponent(r);_h.multiplyMatrices(a.bones[o].matrixWorld,a.boneInverses[o]),t.addScaledVector(Sy.copy(xh).applyMatrix4(_h),s)}}return t.applyMatrix4(this.bindMatrixInverse)}}class fd extends Et{constructor(){super(),this.isBone=!0,this.type="Bone"}}class ud extends _t{constructor(e=null,t=1,a=1,i,r,s,o,c,l=dt,h=dt,d,f){super(null,s,o,c,l,h,i,r,d,f),this.isDataTexture=!0,this.image={data:e,width:t,height:a},this.generateMipmaps=!1,this.flipY=!1,this.unpackAlignment=1}}const Ah=new ze,Ay=new ze;class Vo{constructor(e=[],t=[]){this.uuid=oa(),this.bones=e.slice(0),this.boneInverses=t,this.boneMatrices=null,this.boneTexture=null,this.init()}init(){const e=this.bones,t=this.boneInverses;if(this.boneMatrices=new Float32Array(e.length*16),t.length===0)this.calculateInverses();else if(e.length!==t.length){console.warn("THREE.Skeleton: Number of inverse bone matrices does not match amount of bones."),this.boneInverses=[];for(let a=0,i=this.bones.length;a<i;a++)this.boneInverses.push(new ze)}}calculateInverses(){this.boneInverses.length=0;for(let e=0,t=this.bones.length;e<t;e++){const a=new ze;this.bones[e]&&a.copy(this.bones[e].matrixWorld).invert(),this.boneInverses.push(a)}}pose(){for(let e=0,t=this.bones.length;e<t;e++){const a=this.bones[e];a&&a.matrixWorld.copy(this.boneInverses[e]).invert()}for(let e=0,t=this.bones.length;e<t;e++){const a=this.bones[e];a&&(a.parent&&a.parent.isBone?(a.matrix.copy(a.parent.matrixWorld).invert(),a.matrix.multiply(a.matrixWorld)):a.matrix.copy(a.matrixWorld),a.matrix.decompose(a.position,a.quaternion,a.scale))}}update(){const e=this.bones,t=this.boneInverses,a=this.boneMatrices,i=this.boneTexture;for(let r=0,s=e.length;r<s;r++){const o=e[r]?e[r].matrixWorld:Ay;Ah.multiplyMatrices(o,t[r]),Ah.toArray(a,r*16)}i!==null&&(i.needsUpdate=!0)}clone(){return new Vo(this.bones,this.boneInverses)}computeBoneTexture(){let e=Math.sqrt(this.bones.length*4);e=Math.ceil(e/4)*4,e=Math.max(e,4);const t=new Float32Array(e*e*4);t.set(this.boneMatrices);const a=new ud(t,e,e,Rt,zt);return a.needsUpdate=!0,this.boneMatrices=t,this.boneTexture=a,this}getBoneByName(e){for(let t=0,a=this.bones.length;t<a;t++){const i=this.bones[t];if(i.name===e)return i}}dispose(){this.boneTexture!==null&&(this.boneTexture.dispose(),this.boneTexture=null)}fromJSON(e,t){this.uuid=e.uuid;for(let a=0,i=e.bones.length;a<i;a++){const r=e.bones[a];let s=t[r];s===void 0&&(console.warn("THREE.Skeleton: No bone found with UUID:",r),s=new fd),this.bones.push(s),this.boneInverses.push(new ze().fromArray(e.boneInverses[a]))}return this.init(),this}toJSON(){const e={metadata:{version:4.6,type:"Skeleton",generator:"Skeleton.toJSON"},bones:[],boneInverses:[]};e.uuid=this.uuid;const t=this.bones,a=this.boneInverses;for(let i=0,r=t.length;i<r;i++){const s=t[i];e.bones.push(s.uuid);const o=a[i];e.boneInverses.push(o.toArray())}return e}}class bd extends Vn{static get type(){return"LineBasicMaterial"}constructor(e){super(),this.isLineBasicMaterial=!0,this.color=new Ve(16777215),this.map=null,this.linewidth=1,this.linecap="round",this.linejoin="round",this.fog=!0,this.setValues(e)}copy(e){return super.copy(e),this.color.copy(e.color),this.map=e.map,this.linewidth=e.linewidth,this.linecap=e.linecap,this.linejoin=e.linejoin,this.fog=e.fog,this}}const xr=new O,wr=new O,Th=new ze,ti=new Ai,Qi=new dn,bs=new O,kh=new O;class Ty extends Et{constructor(e=new pt,t=new bd){super(),this.isLine=!0,this.type="Line",this.geometry=e,this.material=t,this.updateMorphTargets()}copy(e,t){return super.copy(e,t),this.material=Array.isArray(e.material)?e.material.slice():e.material,this.geometry=e.geometry,this}computeLineDistances(){const e=this.geometry;if(e.index===null){const t=e.attributes.position,a=[0];for(let i=1,r=t.count;i<r;i++)xr.fromBufferAttribute(t,i-1),wr.fromBufferAttribute(t,i),a[i]=a[i-1],a[i]+=xr.distanceTo(wr);e.setAttribute("lineDistance",new xa(a,1))}else console.warn("THREE.Line.computeLineDistances(): Computation only possible with non-indexed BufferGeometry.");return this}raycast(e,t){const a=this.geometry,i=this.matrixWorld,r=e.params.Line.threshold,s=a.drawRange;if(a.boundingSphere===null&&a.computeBoundingSphere(),Qi.copy(a.boundingSphere),Qi.applyMatrix4(i),Qi.radius+=r,e.ray.intersectsSphere(Qi)===!1)return;Th.copy(i).invert(),ti.copy(e.ray).applyMatrix4(Th);const o=r/((this.scale.x+this.scale.y+this.scale.z)/3),c=o*o,l=this.isLineSegments?2:1,h=a.index,f=a.attributes.position;if(h!==null){const b=Math.max(0,s.start),p=Math.min(h.count,s.start+s.count);for(let g=b,m=p-1;g<m;g+=l){const u=h.getX(g),y=h.getX(g+1),x=$i(this,e,ti,c,u,y);x&&t.push(x)}if(this.isLineLoop){const g=h.getX(p-1),m=h.getX(b),u=$i(this,e,ti,c,g,m);u&&t.push(u)}}else{const b=Math.max(0,s.start),p=Math.min(f.count,s.start+s.count);for(let g=b,m=p-1;g<m;g+=l){const u=$i(this,e,ti,c,g,g+1);u&&t.push(u)}if(this.isLineLoop){const g=$i(this,e,ti,c,p-1,b);g&&t.push(g)}}}updateMorphTargets(){const t=this.geometry.morphAttributes,a=Object.keys(t);if(a.length>0){const i=t[a[0]];if(i!==void 0){this.morphTargetInfluences=[],this.morphTargetDictionary={};for(let r=0,s=i.length;r<s;r++){const o=i[r].name||String(r);this.morphTargetInfluences.push(0),this.morphTargetDictionary[o]=r}}}}}function $i(n,e,t,a,i,r){const s=n.geometry.attributes.position;if(xr.fromBufferAttribute(s,i),wr.fromBufferAttribute(s,r),t.distanceSqToSegment(xr,wr,bs,kh)>a)return;bs.applyMatrix4(n.matrixWorld);const c=e.ray.origin.distanceTo(bs);if(!(c<e.near||c>e.far))return{distance:c,point:kh.clone().applyMatrix4(n.matrixWorld),index:i,face:null,faceIndex:null,barycoord:null,object:n}}const Rh=new O,Ch=new O;class ky extends Ty{constructor(e,t){super(e,t),this.isLineSegments=!0,this.type="LineSegments"}computeLineDistances(){const e=this.geometry;if(e.index===null){const t=e.attributes.position,a=[];for(let i=0,r=t.count;i<r;i+=2)Rh.fromBufferAttribute(t,i),Ch.fromBufferAttribute(t,i+1),a[i]=i===0?0:a[i-1],a[i+1]=a[i]+Rh.distanceTo(Ch);e.setAttribute("lineDistance",new xa(a,1))}else console.warn("THREE.LineSegments.computeLineDistances(): Computation only possible with non-indexed BufferGeometry.");return this}}class vo extends Vn{static get type(){return"PointsMaterial"}constructor(e){super(),this.isPointsMaterial=!0,this.color=new Ve(16777215),this.map=null,this.alphaMap=null,this.size=1,this.sizeAttenuation=!0,this.fog=!0,this.setValues(e)}copy(e){return super.copy(e),this.color.copy(e.color),this.map=e.map,this.alphaMap=e.alphaMap,this.size=e.size,this.sizeAttenuation=e.sizeAttenuation,this.fog=e.fog,this}}const Ih=new ze,yo=new Ai,er=new dn,tr=new O;class Mr extends Et{constructor(e=new pt,t=new vo){super(),this.isPoints=!0,this.type="Points",this.geometry=e,this.material=t,this.updateMorphTargets()}copy(e,t){return super.copy(e,t),this.material=Array.isArray(e.material)?e.material.slice():e.material,this.geometry=e.geometry,this}raycast(e,t){const a=this.geometry,i=this.matrixWorld,r=e.params.Points.threshold,s=a.drawRange;if(a.boundingSphere===null&&a.computeBoundingSphere(),er.copy(a.boundingSphere),er.applyMatrix4(i),er.radius+=r,e.ray.intersectsSphere(er)===!1)return;Ih.copy(i).invert(),yo.copy(e.ray).applyMatrix4(Ih);const o=r/((this.scale.x+this.scale.y+this.scale.z)/3),c=o*o,l=a.index,d=a.attributes.position;if(l!==null){const f=Math.max(0,s.start),b=Math.min(l.count,s.start+s.count);for(let p=f,g=b;p<g;p++){const m=l.getX(p);tr.fromBufferAttribute(d,m),Ph(tr,m,c,i,e,t,this)}}else{const f=Math.max(0,s.start),b=Math.min(d.count,s.start+s.count);for(let p=f,g=b;p<g;p++)tr.fromBufferAttribute(d,p),Ph(tr,p,c,i,e,t,this)}}updateMorphTargets(){const t=this.geometry.morphAttributes,a=Object.keys(t);if(a.length>0){const i=t[a[0]];if(i!==void 0){this.morphTargetInfluences=[],this.morphTargetDictionary={};for(let r=0,s=i.length;r<s;r++){const o=i[r].name||String(r);this.morphTargetInfluences.push(0),this.morphTargetDictionary[o]=r}}}}}function Ph(n,e,t,a,i,r,s){const o=yo.distanceSqToPoint(n);if(o<t){const c=new O;yo.closestPointToPoint(n,c),c.applyMatrix4(a);const l=i.ray.origin.distanceTo(c);if(l<i.near||l>i.far)return;r.push({distance:l,distanceToRay:Math.sqrt(o),point:c,index:e,face:null,faceIndex:null,barycoord:null,object:s})}}class xi extends Jt{static get type(){return"RawShaderMaterial"}constructor(e){super(e),this.isRawShaderMaterial=!0}}class Dh{constructor(e=1,t=0,a=0){return this.radius=e,this.phi=t,this.theta=a,this}set(e,t,a){return this.radius=e,this.phi=t,this.theta=a,this}copy(e){return this.radius=e.radius,this.phi=e.phi,this.theta=e.theta,this}makeSafe(){return this.phi=Math.max(1e-6,Math.min(Math.PI-1e-6,this.phi)),this}setFromVector3(e){return this.setFromCartesianCoords(e.x,e.y,e.z)}setFromCartesianCoords(e,t,a){return this.radius=Math.sqrt(e*e+t*t+a*a),this.radius===0?(this.theta=0,this.phi=0):(this.theta=Math.atan2(e,a),this.phi=Math.acos(Mt(t/this.radius,-1,1))),this}clone(){return new this.constructor().copy(this)}}class Ry extends hn{constructor(e,t=null){super(),this.object=e,this.domElement=t,this.enabled=!0,this.state=-1,this.keys={},this.mouseButtons={LEFT:null,MIDDLE:null,RIGHT:null},this.touches={ONE:null,TWO:null}}connect(){}disconnect(){}dispose(){}update(){}}typeof __THREE_DEVTOOLS__<"u"&&__THREE_DEVTOOLS__.dispatchEvent(new CustomEvent("register",{detail:{revision:Po}}));typeof window<"u"&&(window.__THREE__?console.warn("WARNING: Multiple instances of Three.js being imported."):window.__THREE__=Po);const Wo=`// A model's surface, vertex stage (docs/design.md#rendering): one source for the page (three.js
// RawShaderMaterial, web/src/deform.ts: \`#version 300 es\` and the defines come first) and the
// video (eigendance.export.renderer: \`#version 330\` and the defines come first).
//
// Defines: CPU_PATH — the deformed position is the \`displaced\` attribute (the page's CPU path,
// the video), else texel \`vid\` of the positions pass's float target; HARMONICS — the page's
// harmonics explorer (web/src/shaders.ts TEXELS, which declares \`vid\`, comes before this
// source); MATERIAL — a material's look: UV sets (UV1: a second one) and VERTEX_COLOR;
// REDUCED — a reduced basis (docs/design.md#reduced-basis, the page only): \`deformed\` holds the
// displacements D_j of the m samples, one per texel, and the vertex gathers its ≤ 8 as linear
// blend skinning with translation-only joints, x = rest + Σ_j w_j D_j, from two vec4 attributes
// of sample indices and two of weights (the integers w·2048, exact: web/src/reduced.ts
// WEIGHT_UNITS); READ_BACK (with REDUCED) — drawn as points, vertex v writes its position to
// pixel v of a float target (web/src/reduced.ts GatherPass).
// A drawn vertex's \`vid\` is its welded vertex (docs/design.md#appearance): it reads that
// vertex's deformed position.
precision highp float;
precision highp int;
uniform mat4 modelViewMatrix;
uniform mat4 projectionMatrix;
uniform mat3 normalMatrix;
in vec3 normal;
#ifndef HARMONICS
in float vid;
#endif
#ifdef CPU_PATH
in vec3 displaced;
#else
uniform highp sampler2D deformed;
uniform int deformedWidth;
#endif
out vec3 vViewPosition;
out vec3 vNormal;
#ifdef HARMONICS
uniform int colorHarmonic;
uniform float colorScale;
out float vHarmonic;
#endif
#ifdef REDUCED
in vec4 sampleIndices0;
in vec4 sampleIndices1;
in vec4 sampleWeights0;
in vec4 sampleWeights1;
const float WEIGHT_UNIT = 1.0 / 2048.0;
#ifndef CPU_PATH
in vec3 position;
vec3 sampleDisplacement(float j) {
  int i = int(j + 0.5);
  return texelFetch(deformed, ivec2(i % deformedWidth, i / deformedWidth), 0).xyz;
}
vec3 gatherDisplacement() {
  vec3 d = sampleWeights0.x * sampleDisplacement(sampleIndices0.x)
    + sampleWeights0.y * sampleDisplacement(sampleIndices0.y)
    + sampleWeights0.z * sampleDisplacement(sampleIndices0.z)
    + sampleWeights0.w * sampleDisplacement(sampleIndices0.w)
    + sampleWeights1.x * sampleDisplacement(sampleIndices1.x)
    + sampleWeights1.y * sampleDisplacement(sampleIndices1.y)
    + sampleWeights1.z * sampleDisplacement(sampleIndices1.z)
    + sampleWeights1.w * sampleDisplacement(sampleIndices1.w);
  return d * WEIGHT_UNIT;
}
#endif
#ifdef HARMONICS
// The harmonics explorer's value of U = P U_r: the vertex's samples' texels, weighed.
vec4 gatherHarmonicTexel(int j) {
  vec4 u = vec4(0.0);
  for (int s = 0; s < 4; s++) {
    u += sampleWeights0[s] * harmonicTexel(int(sampleIndices0[s] + 0.5), j);
    u += sampleWeights1[s] * harmonicTexel(int(sampleIndices1[s] + 0.5), j);
  }
  return u * WEIGHT_UNIT;
}
#endif
#endif
#ifdef READ_BACK
uniform int targetWidth;
uniform vec2 targetSize;
#endif
#ifdef MATERIAL
in vec2 texcoord0;
out vec2 vUv0;
#ifdef UV1
in vec2 texcoord1;
out vec2 vUv1;
#endif
#ifdef VERTEX_COLOR
in vec4 vertexColor;
out vec4 vColor;
#endif
#endif

void main() {
  int v = int(vid + 0.5);
#ifdef CPU_PATH
  vec3 p = displaced;
#elif defined(REDUCED)
  vec3 p = position + gatherDisplacement();
#else
  vec3 p = texelFetch(deformed, ivec2(v % deformedWidth, v / deformedWidth), 0).xyz;
#endif
#ifdef HARMONICS
  vHarmonic = 0.0;
  if (colorHarmonic >= 0) {
#ifdef REDUCED
    vec4 u = gatherHarmonicTexel(colorHarmonic / 4);
#else
    vec4 u = harmonicTexel(v, colorHarmonic / 4);
#endif
    int q = colorHarmonic - 4 * (colorHarmonic / 4);
    vHarmonic = (q == 0 ? u.x : q == 1 ? u.y : q == 2 ? u.z : u.w) * colorScale;
  }
#endif
#ifdef MATERIAL
  vUv0 = texcoord0;
#ifdef UV1
  vUv1 = texcoord1;
#endif
#ifdef VERTEX_COLOR
  vColor = vertexColor;
#endif
#endif
  vec4 mv = modelViewMatrix * vec4(p, 1.0);
  vViewPosition = -mv.xyz;
  vNormal = normalize(normalMatrix * normal);
  gl_Position = projectionMatrix * mv;
#ifdef READ_BACK
  vViewPosition = p;
  vec2 pixel = vec2(float(v % targetWidth), float(v / targetWidth)) + 0.5;
  gl_Position = vec4(pixel / targetSize * 2.0 - 1.0, 0.0, 1.0);
  gl_PointSize = 1.0;
#endif
}
`,qo=`// A model's surface, fragment stage (docs/design.md#rendering): one source for the page and the
// video (see surface.vert.glsl). The studio: lights fixed to the camera (a sky/ground ambient, a
// wrapped key, a cool fill, a rim), a soft shoulder and gamma 2.2.
//
// Normals as thesis Fig. 6.4(d): the flat normal of the deformed triangle (screen derivatives of
// the view-space position) weighted \`deformedNormalWeight\` against the rest vertex normal,
// turned to face the camera. Without MATERIAL: the clay (one colour, a broad specular). With
// MATERIAL: glTF metallic-roughness in the same studio (docs/design.md#appearance): base colour
// factor × texture × vertex colour, metallic-roughness, normal (tangent frame from the deformed
// surface's screen derivatives, as three.js without tangents), occlusion and emissive maps,
// alpha MASK / BLEND, UNLIT (KHR_materials_unlit); each map reads its UV set (<MAP>_UV) through
// its KHR_texture_transform matrix.
precision highp float;
precision highp int;
uniform float deformedNormalWeight;
uniform bool wire;
in vec3 vViewPosition;
in vec3 vNormal;
layout(location = 0) out highp vec4 fragColor;

// The studio's lights, in view space (fixed to the camera).
const vec3 KEY_COLOR = vec3(1.0, 0.93, 0.84) * 1.05;
const vec3 FILL_COLOR = vec3(0.55, 0.65, 0.85) * 0.35;
const vec3 GROUND = vec3(0.045, 0.040, 0.038);
const vec3 SKY = vec3(0.16, 0.17, 0.20);

vec3 keyDirection() { return normalize(vec3(-0.5, 0.75, 0.45)); }
vec3 fillDirection() { return normalize(vec3(0.8, 0.05, 0.55)); }

/** Thesis Fig. 6.4(d): the rest vertex normal and the deformed triangle's flat normal mixed. */
vec3 studioNormal() {
  vec3 flatNormal = normalize(cross(dFdx(vViewPosition), dFdy(vViewPosition)));
  vec3 vertexNormal = normalize(vNormal);
  if (dot(vertexNormal, flatNormal) < 0.0) vertexNormal = -vertexNormal;
  return normalize(mix(vertexNormal, flatNormal, deformedNormalWeight));
}

/** The sky/ground ambient seen along n. */
vec3 studioAmbient(vec3 n) { return mix(GROUND, SKY, 0.5 + 0.5 * n.y); }

/** The key (wrapped: soft) and the fill falling on a surface of normal n. */
vec3 studioDirect(vec3 n) {
  float wrapped = max((dot(n, keyDirection()) + 0.3) / 1.3, 0.0);
  return KEY_COLOR * wrapped * wrapped + FILL_COLOR * max(dot(n, fillDirection()), 0.0);
}

/** A cool rim light on the silhouette. */
vec3 studioRim(vec3 n, vec3 view) {
  vec3 back = normalize(vec3(0.3, 0.6, -0.75));
  // pow(x, 4) by multiplication: the same numbers, cheaper on a software GPU.
  float edge = 1.0 - max(dot(n, view), 0.0), edge2 = edge * edge;
  return vec3(0.75, 0.82, 1.0) * (0.35 * max(dot(n, back), 0.0) + 0.25) * edge2 * edge2;
}

/** Linear light → the frame's 8-bit values: a soft shoulder (highlights never clip hard) and
 * gamma 2.2. */
vec3 studioOutput(vec3 color) {
  color = color / (1.0 + 0.25 * color);
  return pow(color * 1.25, vec3(1.0 / 2.2));
}

#ifndef MATERIAL
// --- clay ------------------------------------------------------------------------------------
uniform vec3 baseColor;
#ifdef HARMONICS
uniform int colorHarmonic;
in float vHarmonic;
vec3 diverging(float x) {
  x = clamp(x, -1.0, 1.0);
  vec3 cold = vec3(0.05, 0.12, 0.55), warm = vec3(0.55, 0.02, 0.03), mid = vec3(0.75);
  return x < 0.0 ? mix(mid, cold, -x) : mix(mid, warm, x);
}
#endif

void main() {
  vec3 albedo = baseColor; // linear
#ifdef HARMONICS
  if (colorHarmonic >= 0) albedo = diverging(vHarmonic);
#endif
  if (wire) { fragColor = vec4(pow(albedo, vec3(1.0 / 2.2)), 1.0); return; }
  vec3 n = studioNormal();
  vec3 view = normalize(vViewPosition);
  vec3 light = studioAmbient(n) + studioDirect(n);
  float h = max(dot(n, normalize(keyDirection() + view)), 0.0), h3 = h * h * h, h6 = h3 * h3;
  float h12 = h6 * h6;
  float spec = h12 * h12 * 0.18; // pow(h, 24)
  vec3 color = albedo * light + studioRim(n, view) + vec3(spec);
  fragColor = vec4(studioOutput(color), 1.0);
}

#else
// --- a glTF material ---------------------------------------------------------------------------
uniform vec4 baseColorFactor;
uniform float metallicFactor;
uniform float roughnessFactor;
uniform vec3 emissiveFactor;
uniform float alphaCutoff;
// The studio's light on a material, brighter than on the clay: a surface facing the camera
// shows about its own colour, as in a glTF viewer (the clay's moodier light would darken it).
const float MATERIAL_EXPOSURE = 1.5;
in vec2 vUv0;
#ifdef UV1
in vec2 vUv1;
#endif
#ifdef VERTEX_COLOR
in vec4 vColor;
#endif
#ifdef BASE_MAP
uniform sampler2D baseMap;
uniform mat3 baseMapTransform;
#endif
#ifdef NORMAL_MAP
uniform sampler2D normalMap;
uniform mat3 normalMapTransform;
uniform vec2 normalScale;
#endif
#ifdef METALLIC_ROUGHNESS_MAP
uniform sampler2D metallicRoughnessMap;
uniform mat3 metallicRoughnessMapTransform;
#endif
#ifdef OCCLUSION_MAP
uniform sampler2D occlusionMap;
uniform mat3 occlusionMapTransform;
uniform float occlusionStrength;
#endif
#ifdef EMISSIVE_MAP
uniform sampler2D emissiveMap;
uniform mat3 emissiveMapTransform;
#endif

/** UVs through a KHR_texture_transform matrix (identity without one). */
vec2 mapUv(mat3 transform, vec2 uv) { return (transform * vec3(uv, 1.0)).xy; }

/** Linear → sRGB, exactly (an unlit material shows its colour as authored). */
vec3 srgb(vec3 c) {
  c = clamp(c, 0.0, 1.0);
  return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(0.0031308, c));
}

#ifdef NORMAL_MAP
/** Tangent frame from screen derivatives of the deformed surface (three.js getTangentFrame):
 * it turns with the surface as it dances. */
mat3 tangentFrame(vec3 eye, vec3 n, vec2 uv) {
  vec3 q0 = dFdx(eye), q1 = dFdy(eye);
  vec2 st0 = dFdx(uv), st1 = dFdy(uv);
  vec3 q1perp = cross(q1, n), q0perp = cross(n, q0);
  vec3 t = q1perp * st0.x + q0perp * st1.x;
  vec3 b = q1perp * st0.y + q0perp * st1.y;
  float det = max(dot(t, t), dot(b, b));
  float scale = det == 0.0 ? 0.0 : inversesqrt(det);
  return mat3(t * scale, b * scale, n);
}
#endif

/** Split-sum environment BRDF (Karis's analytic fit, as three.js DFGApprox). */
vec2 environmentBrdf(float roughness, float dotNV) {
  vec4 r = roughness * vec4(-1.0, -0.0275, -0.572, 0.022) + vec4(1.0, 0.0425, 1.04, -0.04);
  float a004 = min(r.x * r.x, exp2(-9.28 * dotNV)) * r.x + r.y;
  return vec2(-1.04, 1.04) * a004 + r.zw;
}

/** The studio seen in direction r by a surface of this roughness: the ambient, and the key and
 * fill as soft boxes, blurred toward the light falling on a surface facing r as it roughens. */
vec3 studioRadiance(vec3 r, float roughness) {
  float key = smoothstep(0.82, 0.97, dot(r, keyDirection()));
  float fill = smoothstep(0.80, 0.97, dot(r, fillDirection()));
  vec3 sharp = studioAmbient(r) + 2.5 * KEY_COLOR * key + 1.5 * FILL_COLOR * fill;
  return mix(sharp, studioAmbient(r) + studioDirect(r), roughness);
}

/** A metallic-roughness surface lit by the studio: diffuse from the ambient and the lights,
 * specular from the studio's radiance with multiple scattering (three.js
 * computeMultiscattering), both occluded by \`ao\`. */
vec3 studioSurface(vec3 albedo, float metallic, float roughness, float ao, vec3 n, vec3 view) {
  vec3 diffuseColor = albedo * (1.0 - metallic);
  vec3 specularColor = mix(vec3(0.04), albedo, metallic);
  float dotNV = clamp(dot(n, view), 1e-4, 1.0);
  vec2 fab = environmentBrdf(roughness, dotNV);
  vec3 single = specularColor * fab.x + fab.y;
  float ems = 1.0 - (fab.x + fab.y);
  vec3 average = specularColor + (1.0 - specularColor) * 0.047619;
  vec3 multi = single * average / (1.0 - ems * average) * ems;
  vec3 light = studioAmbient(n) * ao + studioDirect(n);
  vec3 radiance = studioRadiance(reflect(-view, n), roughness);
  return diffuseColor * light + (radiance * single + light * multi) * ao;
}

void main() {
  vec4 base = baseColorFactor;
#ifdef VERTEX_COLOR
  base *= vColor;
#endif
#ifdef BASE_MAP
  base *= texture(baseMap, mapUv(baseMapTransform, BASE_MAP_UV));
#endif
#ifdef ALPHA_MASK
  if (base.a < alphaCutoff) discard;
#endif
#ifdef ALPHA_BLEND
  float alpha = base.a;
#else
  float alpha = 1.0;
#endif
#ifdef UNLIT
  fragColor = vec4(srgb(base.rgb), alpha);
#else
  vec3 n = studioNormal();
  vec3 view = normalize(vViewPosition);
#ifdef NORMAL_MAP
  vec2 uv = mapUv(normalMapTransform, NORMAL_MAP_UV);
  vec3 mapped = texture(normalMap, uv).xyz * 2.0 - 1.0;
  mapped.xy *= normalScale;
  mat3 frame = tangentFrame(-vViewPosition, n, uv);
  float side = gl_FrontFacing ? 1.0 : -1.0;
  frame[0] *= side;
  frame[1] *= side;
  n = normalize(frame * mapped);
#endif
  float metallic = metallicFactor, roughness = roughnessFactor;
#ifdef METALLIC_ROUGHNESS_MAP
  vec4 texel = texture(metallicRoughnessMap, mapUv(metallicRoughnessMapTransform,
                                                   METALLIC_ROUGHNESS_MAP_UV));
  roughness *= texel.g;
  metallic *= texel.b;
#endif
  metallic = clamp(metallic, 0.0, 1.0);
  roughness = clamp(roughness, 0.0525, 1.0);
  float ao = 1.0;
#ifdef OCCLUSION_MAP
  ao += occlusionStrength * (texture(occlusionMap, mapUv(occlusionMapTransform,
                                                         OCCLUSION_MAP_UV)).r - 1.0);
#endif
  vec3 emissive = emissiveFactor;
#ifdef EMISSIVE_MAP
  emissive *= texture(emissiveMap, mapUv(emissiveMapTransform, EMISSIVE_MAP_UV)).rgb;
#endif
  vec3 color = MATERIAL_EXPOSURE * studioSurface(base.rgb, metallic, roughness, ao, n, view)
    + studioRim(n, view) * (1.0 - 0.5 * metallic) + emissive;
  fragColor = vec4(studioOutput(color), alpha);
#endif
}
#endif
`,Cy=`// The studio backdrop of a view, drawn first over its whole viewport (docs/design.md#rendering).
precision highp float;
in vec3 position;
out vec2 vUv;
void main() {
  vUv = position.xy * 0.5 + 0.5;
  gl_Position = vec4(position.xy, 0.999, 1.0);
}
`,Iy=`// A vertical gradient with a soft light pool behind the model (colours linear).
precision highp float;
uniform vec3 top;
uniform vec3 bottom;
uniform float aspect;
in vec2 vUv;
layout(location = 0) out highp vec4 fragColor;
void main() {
  vec3 color = mix(bottom, top, smoothstep(0.0, 1.0, vUv.y));
  vec2 p = (vUv - vec2(0.5, 0.58)) * vec2(aspect, 1.0);
  color += vec3(0.012, 0.011, 0.010) * exp(-3.5 * dot(p, p)); // linear, like top and bottom
  fragColor = vec4(pow(color, vec3(1.0 / 2.2)), 1.0);
}
`,Py=`// A soft contact shadow: the unit square of the floor plane (x, z in [-1, 1]), placed under the
// model by the model matrix, blended over what is drawn.
precision highp float;
uniform mat4 modelViewMatrix;
uniform mat4 projectionMatrix;
in vec3 position;
out vec2 vPlane;
void main() {
  vPlane = position.xz;
  gl_Position = projectionMatrix * modelViewMatrix * vec4(position, 1.0);
}
`,Dy=`// An elliptic dark pool, transparent at its edge.
precision highp float;
uniform float strength;
in vec2 vPlane;
layout(location = 0) out highp vec4 fragColor;
void main() {
  float r = dot(vPlane, vPlane);
  fragColor = vec4(0.0, 0.0, 0.0, strength * exp(-3.0 * r) * (1.0 - smoothstep(0.7, 1.0, r)));
}
`,Xo=`
precision highp float;
precision highp int;
precision highp sampler2D;
uniform sampler2D harmonics;
uniform int texWidth;
in float vid;

vec4 harmonicTexel(int v, int j) {
  int index = v * K4 + j;
  return texelFetch(harmonics, ivec2(index % texWidth, index / texWidth), 0);
}
`;function Ny(n){const e=[...Array(n).keys()],t=`
uniform vec4 weights[WEIGHTS];
uniform int targetWidth;
uniform vec2 targetSize;
${e.map(i=>`out vec3 vPosition${i};`).join(`
`)}
void main() {
  int v = int(vid + 0.5);
${e.map(i=>`  vec3 d${i} = vec3(0.0);`).join(`
`)}
  for (int j = 0; j < K4; j++) {
    vec4 u = harmonicTexel(v, j);
    int b = 3 * j;
${e.map(i=>`    d${i} += vec3(dot(u, weights[b + ${3*i} * K4]), dot(u, weights[b + ${3*i} * K4 + 1]), dot(u, weights[b + ${3*i} * K4 + 2]));`).join(`
`)}
  }
${e.map(i=>`  vPosition${i} = position + d${i};`).join(`
`)}
  vec2 pixel = vec2(float(v % targetWidth), float(v / targetWidth)) + 0.5;
  gl_Position = vec4(pixel / targetSize * 2.0 - 1.0, 0.0, 1.0);
  gl_PointSize = 1.0;
}
`,a=`
precision highp float;
${e.map(i=>`in vec3 vPosition${i};
layout(location = ${i}) out highp vec4 out${i};`).join(`
`)}
void main() {
${e.map(i=>`  out${i} = vec4(vPosition${i}, 1.0);`).join(`
`)}
}
`;return{vertex:t,fragment:a}}const Uy=2048,Fy={sampleIndices0:0,sampleIndices1:4,sampleWeights0:0,sampleWeights1:4};function md(n,e){let t=n.indices instanceof Uint16Array?n.indices:Float32Array.from(n.indices),a=new Uint16Array(n.weights.length);for(let s=0;s<a.length;s++)a[s]=Math.round(n.weights[s]*Uy);e&&(t=Nh(t,e),a=Nh(a,e));const i=new yh(t,8),r=new yh(a,8);return{sampleIndices0:new Cn(i,4,0),sampleIndices1:new Cn(i,4,4),sampleWeights0:new Cn(r,4,0),sampleWeights1:new Cn(r,4,4)}}function Nh(n,e){const t=new n.constructor(e.length*8);for(let a=0;a<e.length;a++)t.set(n.subarray(8*e[a],8*e[a]+8),8*a);return t}function Ly(n){const e=new pt;return e.setAttribute("position",new Be(new Float32Array(3*n),3)),e.setAttribute("vid",new Be(new Float32Array(n).map((t,a)=>a),1)),e}class jy{constructor(e,t,a,i,r,s,o){this.geometry=e,this.n=t,this.width=Math.min(t,a);const c=Math.ceil(t/this.width);this.target=new Sa(this.width,c,{type:zt,format:Rt,depthBuffer:!1,minFilter:dt,magFilter:dt,generateMipmaps:!1}),this.material=new xi({glslVersion:Ea,defines:{K4:o,HARMONICS:1,REDUCED:1,READ_BACK:1},uniforms:{deformed:{value:null},deformedWidth:{value:i},harmonics:{value:r},texWidth:{value:s},colorHarmonic:{value:-1},colorScale:{value:1},targetWidth:{value:this.width},targetSize:{value:new De(this.width,c)}},vertexShader:Xo+Wo,fragmentShader:`
precision highp float;
in vec3 vViewPosition; // READ_BACK: the vertex's position
layout(location = 0) out highp vec4 outPosition;
void main() { outPosition = vec4(vViewPosition, 1.0); }`,depthTest:!1,depthWrite:!1});const l=new pt;for(const d of["position","normal","vid",...Object.keys(Fy)])l.setAttribute(d,e.getAttribute(d));const h=new Mr(l,this.material);h.frustumCulled=!1,this.scene.add(h)}geometry;n;target;width;material;scene=new Ho;camera=new Bo(-1,1,1,-1,0,1);read(e,t){this.material.uniforms.deformed.value=t;const a=e.getRenderTarget(),i=e.getScissorTest();e.setScissorTest(!1),e.setRenderTarget(this.target),e.render(this.scene,this.camera);const r=new Float32Array(this.target.width*this.target.height*4);e.readRenderTargetPixels(this.target,0,0,this.target.width,this.target.height,r),e.setRenderTarget(a),e.setScissorTest(i);const s=new Float32Array(this.n*3);for(let o=0;o<this.n;o++)s[3*o]=r[4*o],s[3*o+1]=r[4*o+1],s[3*o+2]=r[4*o+2];return s}dispose(){this.target.dispose(),this.material.dispose()}}const Uh=new WeakMap;function Oy(n,e,t,a){const i=n.reduced,{m:r}=i;let s=Uh.get(n);s||Uh.set(n,s=new Float32Array(3*r));const o=n.harmonics,c=4*n.k4;for(let b=0;b<r;b++){let p=0,g=0,m=0;const u=b*c;for(let y=0;y<n.k4;y++){const x=o[u+4*y],v=o[u+4*y+1],E=o[u+4*y+2],_=o[u+4*y+3],A=12*y;p+=x*e[A]+v*e[A+1]+E*e[A+2]+_*e[A+3],g+=x*e[A+4]+v*e[A+5]+E*e[A+6]+_*e[A+7],m+=x*e[A+8]+v*e[A+9]+E*e[A+10]+_*e[A+11]}s[3*b]=p,s[3*b+1]=g,s[3*b+2]=m}const l=a?a.length:n.n,h=t??new Float32Array(l*3),{weights:d,indices:f}=i;for(let b=0;b<l;b++){const p=a?a[b]:b;let g=0,m=0,u=0;for(let y=8*p;y<8*p+8;y++){const x=3*f[y],v=d[y];g+=v*s[x],m+=v*s[x+1],u+=v*s[x+2]}h[3*b]=n.vertices[3*p]+g,h[3*b+1]=n.vertices[3*p+1]+m,h[3*b+2]=n.vertices[3*p+2]+u}return h}function zy(n,e){const{weights:t,indices:a}=n.reduced,i=4*n.k4,r=new Float32Array(n.n);for(let s=0;s<n.n;s++){let o=0;for(let c=8*s;c<8*s+8;c++)o+=t[c]*n.harmonics[a[c]*i+e];r[s]=o}return r}function By(n,e){const t=n.envelope??{},a=d=>{const f=d===void 0?[0]:Array.isArray(d)?d:[d];return Float64Array.from({length:e},(b,p)=>f.length===1?f[0]:f[p])},i=a(t.attack),r=a(t.release),s=a(t.threshold),o=t.auto_range??!1,c=!o&&[i,r,s].every(d=>d.every(f=>f===0)),l=n.smoothing??0,h=c?`${l}`:`${l}|${o}|${i}|${r}|${s}`;return{attack:i,release:r,threshold:s,autoRange:o,identity:c,key:h}}function Fh(n,e){const t=e/100*(n.length-1),a=Math.floor(t),i=Math.min(a+1,n.length-1);return n[a]+(t-a)*(n[i]-n[a])}function Gy(n,e,t,a,i){if(i.identity)return n;const r=Float64Array.from(n);if(i.autoRange){const d=new Float64Array(e);for(let f=0;f<t;f++){for(let u=0;u<e;u++)d[u]=r[u*t+f];const b=d.slice().sort(),p=Fh(b,5),g=Fh(b,95),m=g-p;for(let u=0;u<e;u++)r[u*t+f]=m<=1e-6?0:Math.min(1,Math.max(0,(d[u]-p)/m))}}const s=d=>d>0?Math.exp(-1/(a*d)):0,o=Array.from(i.attack,s),c=Array.from(i.release,s),l=new Float32Array(n.length),h=new Float64Array(t);for(let d=0;d<e;d++)for(let f=0;f<t;f++){let b=r[d*t+f];b<i.threshold[f]&&(b=0);const p=b>h[f]?o[f]:c[f];h[f]=b+p*(h[f]-b),l[d*t+f]=h[f]}return l}function pd(n,e){if(!e)return n;const t=e.reduced?{k:e.k,construction:"reduced",samples:e.reduced.asked,placed:e.reduced.m}:{k:e.k,construction:"exact",samples:null,placed:null};return{...n,basis:t}}const ai={gain:1,smoothing:0,deformedNormalWeight:.4,shading:"smooth",materials:!0};function _r(n){const e=n.look??{};return{gain:n.gain??ai.gain,smoothing:n.smoothing??ai.smoothing,deformedNormalWeight:e.deformed_normal_weight??ai.deformedNormalWeight,shading:e.shading??ai.shading,materials:e.materials??ai.materials}}function Lh(n,e){return{...n,version:3,gain:e.gain,smoothing:e.smoothing,offset:n.offset??0,modes:n.modes??null,look:{...n.look,deformed_normal_weight:e.deformedNormalWeight,shading:e.shading,materials:e.materials}}}function jh(n,e,t,a=n.values){const i=n.bands,r=t??new Float32Array(i),s=Math.min(Math.max(e*n.rate,0),n.frames-1),o=Math.floor(s),c=Math.min(o+1,n.frames-1),l=s-o;for(let h=0;h<i;h++)r[h]=(1-l)*a[o*i+h]+l*a[c*i+h];return r}function Hy(n,e){if(!(e>0))return n.values;const t=n.bands,a=Math.exp(-1/(n.rate*e)),i=new Float32Array(n.values.length),r=new Float64Array(t);for(let s=0;s<n.frames;s++)for(let o=0;o<t;o++)r[o]=a*r[o]+(1-a)*n.values[s*t+o],i[s*t+o]=r[o];return i}function Vy(n,e){const t=n.pulse??{},[a,i]=t.range??[0,1],r=Float64Array.from({length:e},(o,c)=>{const l=(c+.5)/e;return l>=a&&l<=i?1:0}),s=Int32Array.from([...r.keys()].filter(o=>r[o]===1));return{amount:t.amount??0,decay:t.decay??.15,source:t.source??"beats",routed:r,targets:s}}function Oh(n,e){return e.amount>0?e.source==="onsets"?n.onsets:Tr(n)?n.beats:new Float32Array(0):new Float32Array(0)}function zh(n,e,t){const a=new Float32Array(t.length).fill(1);if(e.source!=="onsets"&&Tr(n))for(let i=0;i<t.length;i++)a[i]=Il(n,t[i]).accent;return a}function xo(n,e,t,a){if(!(n.amount>0)||e.length===0||t<e[0])return 0;let i=0,r=e.length-1;for(;i<r;){const o=i+r+1>>1;e[o]<=t?i=o:r=o-1}const s=a?a[i]:1;return n.amount*s*Math.exp(-Math.max(0,t-e[i])/n.decay)}function Wy(n,e){const t=n.length,a=new Float64Array(e);for(let i=0;i<e;i++)a[i]=t===e?n[i]:n[Math.min(t-1,Math.floor((i+.5)*t/e))];return a}function Ir(n,e){const t=new Int32Array(n.transfer.length);n.transfer.forEach((r,s)=>{t[s]=Math.min(e-1,Math.floor(r*e))});const{gain:a,smoothing:i}=_r(n);return{k:e,harmonicOfBand:t,amplification:Wy(n.amplification,e),gain:a,smoothing:i,envelope:By(n,n.transfer.length),pulse:Vy(n,e),sections:Float64Array.from(n.sections??[])}}function qy(n,e,t){const a=n.sections;if(!a||a.length===0||e.length===0)return 1;let i=0;for(;i<e.length&&e[i]<=t;)i++;return a[i%a.length]}function gd(n){const e=new Set;return n.harmonicOfBand.forEach(t=>{n.amplification[t]!==0&&e.add(t)}),[...e].sort((t,a)=>t-a)}function Ko(n,e,t=n.gain,a,i=0){const r=a??new Float64Array(n.k),s=new Float64Array(n.k),o=n.harmonicOfBand.length;for(let c=0;c<o;c++)s[n.harmonicOfBand[c]]+=e[c];if(i!==0){const c=n.pulse.targets;for(let l=0;l<c.length;l++)s[c[l]]+=i}for(let c=0;c<n.k;c++)r[c]=t*n.amplification[c]*s[c]+1;return r}function Xy(n,e,t){const a=t??new Float32Array(n.k4*12);a.fill(0);for(let i=0;i<n.k;i++){const r=i>>2,s=i&3,o=e[i]-1;for(let c=0;c<3;c++)a[(3*r+c)*4+s]=o*n.coefficients[3*i+c]}return a}function Ky(n,e){let t=0;const a=new Int32Array(4*n);for(let o=0;o<n;o++)for(let c=0;c<4;c++){const l=12*o+c;(e[l]!==0||e[l+4]!==0||e[l+8]!==0)&&(a[t++]=4*o+c)}const i=new Float32Array(t),r=new Float32Array(t),s=new Float32Array(t);for(let o=0;o<t;o++){const c=12*(a[o]>>2)+(a[o]&3);i[o]=e[c],r[o]=e[c+4],s[o]=e[c+8]}return{index:a.subarray(0,t),x:i,y:r,z:s}}const Jy=64*2**20,Bh=new WeakMap;function Yy(n,e){let t=Bh.get(n);t||(t=new Map,Bh.set(n,t));let a=t.get(e);if(a)t.delete(e);else{const{n:i,harmonics:r}=n,s=4*n.k4;a=new Float32Array(i);for(let o=0;o<i;o++)a[o]=r[o*s+e];for(;t.size&&(t.size+1)*4*i>Jy;)t.delete(t.keys().next().value)}return t.set(e,a),a}function Va(n,e,t,a){if(n.reduced)return Oy(n,e,t,a);const i=a?a.length:n.n,r=t??new Float32Array(i*3),s=n.harmonics,o=4*n.k4,c=n.vertices,{index:l,x:h,y:d,z:f}=Ky(n.k4,e),b=l.length;if(!a){r.set(c.subarray(0,3*i));for(let p=0;p<b;p++){const g=Yy(n,l[p]),m=h[p],u=d[p],y=f[p];for(let x=0,v=0;x<i;x++,v+=3){const E=g[x];r[v]+=E*m,r[v+1]+=E*u,r[v+2]+=E*y}}return r}for(let p=0;p<i;p++){const g=a[p];let m=0,u=0,y=0;const x=g*o;for(let v=0;v<b;v++){const E=s[x+l[v]];m+=E*h[v],u+=E*d[v],y+=E*f[v]}r[3*p]=c[3*g]+m,r[3*p+1]=c[3*g+1]+u,r[3*p+2]=c[3*g+2]+y}return r}class Gh{generations=[];current=-1;get size(){return this.generations.length}get shown(){return this.generations[this.current]??null}add(e,t,a=""){return this.generations.push({mappings:e,parent:t,note:a}),this.current=this.generations.length-1,this.current}entries(){const e=new Map;this.generations.forEach((i,r)=>{e.set(i.parent,[...e.get(i.parent)??[],r])});const t=[],a=(i,r)=>{const s=this.generations[i],o=s.parent===null?`first${s.note?` · ${s.note}`:""}`:`bred from ${s.parent+1}`;t.push({index:i,depth:r,label:`${"  ".repeat(r)}${r?"└ ":""}${i+1} · ${o}`});for(const c of e.get(i)??[])a(c,r+1)};for(const i of e.get(null)??[])a(i,0);return t}neighbour(e){const t=this.entries().map(i=>i.index),a=t.indexOf(this.current);return t[Math.max(0,Math.min(t.length-1,a+e))]??this.current}}const wo="eigendance.session",vd="eigendance-session";function Jo(n,e={},t,a){return{format:wo,version:1,histories:n,rigs:e,...t?{song:t}:{},...a?{model:a}:{}}}function Gn(n){const e=qn();Zo(Yo(Jo(n.histories??e?.histories??{},n.rigs??e?.rigs??{},n.song??e?.song,n.model??e?.model),e?.names))}let Mo={};function Zy(n){Mo={};for(const e of[...n.meshes,...n.rigs??[],...n.songs])Mo[e.id]=e.name}function Yo(n,e={}){const t={};for(const a of Qy(n)){const i=Mo[a]??e[a];i!==void 0&&(t[a]=i)}return{...n,names:t}}function Qy(n){return[...Object.keys(n.histories),...Object.keys(n.rigs??{}),...n.song?[n.song.id]:[],...n.model?[n.model.id]:[]]}function yd(n,e){const t=n.names??{},a=new Set,i=new Set,r=new Map,s=y=>x=>{if(y.some(E=>E.id===x))return x;const v=y.filter(E=>x in t&&E.name===t[x]);return v.length===1?r.set(x,v[0].id):(v.length?i:a).add(t[x]??x),r.get(x)??x},o=s(e.meshes),c=s(e.rigs??[]),l=s(e.songs),h=(y,x)=>Object.fromEntries(Object.entries(y).map(([v,E])=>[x(v),E])),d=n.model,f=h(n.histories,o),b=h(n.rigs??{},c),p={...n,histories:f,rigs:b,...n.song?{song:{...n.song,id:l(n.song.id)}}:{},...d?{model:{...d,id:(d.kind==="rig"?c:o)(d.id)}}:{}};p.names=Object.fromEntries(Object.entries(t).map(([y,x])=>[r.get(y)??y,x]));const g=y=>x=>y.some(v=>v.id===x),m=Object.keys(f).filter(g(e.meshes)).length+Object.keys(b).filter(g(e.rigs??[])).length,u=[a.size?`not served any more: ${[...a].join(", ")}`:"",i.size?`served twice, not guessed: ${[...i].join(", ")}`:""];return{session:p,count:m,missing:u.filter(Boolean).join("; ")}}function xd(n,{session:e,count:t,missing:a},i){n.gallery.restore(e.histories),n.rigs.restore(e.rigs??{});const r=qn(),s=(c,...l)=>Object.fromEntries(Object.entries(c??{}).filter(([h])=>!l.some(d=>h in d)));Zo(Yo(Jo({...s(r?.histories,i.histories,e.histories),...e.histories},{...s(r?.rigs,i.rigs??{},e.rigs??{}),...e.rigs},e.song??r?.song,e.model??r?.model),{...r?.names,...e.names}));const o=`${t} ${t===1?"model":"models"} restored`;return a?`${o}; ${a}`:o}function $y(n,e){const t=qn();if(!t)return e;const a=yd(t,e);return xd(n,a,t),a.missing&&n.messages.error(`The session kept in this browser: ${a.missing} (kept for when it is served again); the rest is restored`),e}function fr(n){return n.rigs.active?n.rigs.rig?{kind:"rig",id:n.rigs.rig.id}:void 0:n.library.meshId?{kind:"mesh",id:n.library.meshId}:void 0}function ex(n,e){const t=e?void 0:qn()?.model;return t&&wd(n,t)?t.kind==="rig"?{rig:t.id,mesh:null}:{rig:null,mesh:t.id}:{rig:tx(n,e),mesh:null}}function tx(n,e){if(e)return null;const t=n.rigs??[],a=n.first;if(a?.kind==="rig"&&t.some(r=>r.id===a.id))return a.id;if(n.meshes.length)return null;const i=t.filter(r=>r.origin==="file"||r.origin==="upload");return i.length?i[i.length-1].id:null}async function ax(n,e,t){const a=fr(n);!e||!wd(t,e)||a?.kind===e.kind&&a.id===e.id||(e.kind==="rig"?await n.openRig(e.id):await n.showMesh(e.id))}function wd(n,e){return(e.kind==="rig"?n.rigs??[]:n.meshes).some(a=>a.id===e.id)}function pi(n){const e=n.library.songId,t=n.transport;return e?{id:e,time:t.following?0:t.now()}:void 0}async function ms(n,e){const t=qn()?.song,a=t&&e.songs.some(i=>i.id===t.id);await n.library.loadSong(n.options.song??(a?t.id:e.songs[0].id)),t?.id===n.library.songId&&Md(n,t.time),Gn({song:pi(n)})}async function nx(n,e,t){return e?t.songs.some(a=>a.id===e.id)?((e.id!==n.library.songId||n.transport.following)&&await n.changeSong(e.id),n.transport.pause(),Md(n,e.time),!0):!1:!0}function Md(n,e){const t=n.transport.duration;n.transport.seek(e<t-.5?e:0),n.viewer.requestDraw()}function _d(n){let e;try{e=JSON.parse(n)}catch{throw new Error("this file is not JSON")}const t=e;if(!t||t.format!==wo||typeof t.histories!="object"||t.histories===null)throw new Error(`this file is not an eigendance session (format "${wo}")`);for(const[r,s]of Object.entries(t.histories))if(!Array.isArray(s?.generations)||!s.generations.every(o=>Array.isArray(o?.mappings)&&o.mappings.every(c=>Array.isArray(c?.transfer))))throw new Error(`the gallery of model ${r} in this session is not readable`);for(const[r,s]of Object.entries(t.rigs??{}))if(!Array.isArray(s?.generations)||!s.generations.every(o=>Array.isArray(o)&&o.every(c=>Array.isArray(c?.transfer)))||!Array.isArray(s.selected))throw new Error(`the galleries of rig ${r} in this session are not readable`);const a=t.song;if(a!==void 0&&(typeof a?.id!="string"||!Number.isFinite(a.time)))throw new Error("the song of this session is not readable");const i=t.model;if(i!==void 0&&(typeof i?.id!="string"||i.kind!=="mesh"&&i.kind!=="rig"))throw new Error("the model of this session is not readable");if(t.names!==void 0&&(typeof t.names!="object"||t.names===null||!Object.values(t.names).every(r=>typeof r=="string")))throw new Error("the names of this session are not readable");return t}function Zo(n){try{localStorage.setItem(vd,JSON.stringify(n))}catch{}}function ix(n,e){const t=s=>Object.fromEntries(Object.entries(s??{}).filter(([o])=>o!==e)),{song:a,model:i,...r}=n;return{...r,histories:t(n.histories),rigs:t(n.rigs),names:t(n.names),...a&&a.id!==e?{song:a}:{},...i&&i.id!==e?{model:i}:{}}}function rx(n,e){n.gallery.forget(e),n.rigs.sessions.forget(e);const t=qn();t&&Zo(ix(t,e))}function qn(){try{const n=localStorage.getItem(vd);return n?_d(n):null}catch{return null}}const sx=.12,Ed=n=>({amount:n,decay:sx,source:"beats",routed:new Float64Array(0),targets:new Int32Array(0)}),ox=Ed(.5),cx=Ed(1);function hx(n,e,t){const a=e&&Tr(e)?e.beats:null,i=a&&e.meter>0?e.downbeats:null,r=a?Math.max(xo(ox,a,t),i?xo(cx,i,t):0):0;n.style.setProperty("--beat",r.toFixed(3));const s=i?` in ${e.meter}/4, brighter on each bar's first beat`:"",o=e?.sections.length?`; ${e.sections.length+1} sections (a mark along the bottom edge where each starts)`:"",c=a?`${e.tempo.toFixed(0)} BPM${s}: the top edge ticks on each beat${o}`:"no beat detected: the dance follows the loudness";n.dataset.tempo!==c&&(n.dataset.tempo=c,n.title=`the song's loudness per band now: bass on the left, treble on the right; ${c}`),lx(n,e)}function lx(n,e){const t=e?.sections??new Float32Array(0),a=e?`${e.name} ${e.duration} ${t.join(",")}`:"";n.dataset.sections!==a&&(n.dataset.sections=a,n.querySelectorAll(":scope > i.section").forEach(i=>i.remove()),t.forEach(i=>{const r=document.createElement("i");r.className="section",r.style.left=`${(100*i/e.duration).toFixed(3)}%`,r.dataset.start=i.toFixed(2),n.append(r)}))}const Sd="#ffb347",dx="#5a6070";function fx(n,e){const t=e.length,a=n.getElementsByTagName("span");if(a.length!==t){for(const i of[...a])i.remove();n.prepend(...Array.from({length:t},(i,r)=>{const s=document.createElement("span");return s.style.background=`hsl(${30+200*(r/t)}, 80%, 55%)`,s}))}for(let i=0;i<t;i++){const r=Math.max(0,Math.min(1,e[i]));a[i].style.transform=`scaleY(${r.toFixed(3)})`,a[i].style.opacity=(.45+.55*r).toFixed(3)}}function ux(n,e){const t=n.getContext("2d"),{width:a,height:i}=n;t.clearRect(0,0,a,i),t.fillStyle="#ffffff14",t.fillRect(0,0,a,i);const r=e.harmonicOfBand.length;t.fillStyle=Sd,e.harmonicOfBand.forEach((s,o)=>{const c=(o+.5)/r*a,l=i-2-(s+.5)/e.k*(i-4);t.fillRect(c-1,l-1,2.5,2.5)})}function bx(n,e){const t=new Float64Array(n.k);for(let a=0;a<n.k;a++){const i=Math.hypot(e[3*a],e[3*a+1],e[3*a+2]);t[a]=n.gain*n.amplification[a]*i}return t}function mx(n,e,t){const a=n.getContext("2d"),{width:i,height:r}=n;a.clearRect(0,0,i,r),a.fillStyle="#ffffff14",a.fillRect(0,0,i,r),a.fillStyle="#444b58",a.fillRect(0,r/2,i,1);const s=new Set(e.harmonicOfBand),o=e.k;let c=0;for(let l=0;l<o;l++)c=Math.max(c,Math.abs(t[l]));for(let l=0;l<o;l++){const h=Math.max(-1,Math.min(1,t[l]/(c||1)))*(r/2-1);if(!h)continue;a.fillStyle=s.has(l)?Sd:dx;const d=Math.floor(l/o*i);a.fillRect(d,r/2-Math.max(h,0),Math.max(1,Math.ceil(i/o)),Math.max(1,Math.abs(h)))}}const px=24;function gx(n){if(!n.length)return"still";const[e,t]=[n[0],n[n.length-1]];return e===t?`harmonic ${e}`:`harmonics ${e}–${t}`}class vx{constructor(e,t,a){this.motion=e,this.events=t,this.size=a,I("back").addEventListener("click",()=>this.step(-1)),I("forward").addEventListener("click",()=>this.step(1)),I("generation").addEventListener("change",i=>{this.setGeneration(Number(i.target.value))}),I("breed").addEventListener("click",()=>{this.events.guard("Breeding failed",()=>this.breed())})}motion;events;size;histories=new Map;meshId="";prepared=[];selected=new Set;tiles=[];restoredSelection=new Map;get history(){let e=this.histories.get(this.meshId);return e||(e=new Gh,this.histories.set(this.meshId,e)),e}mappings(){return this.history.shown?.mappings??[]}get generation(){return this.history.current}get generationCount(){return this.history.size}get tileCount(){return this.tiles.length}get selection(){return[...this.selected].sort((e,t)=>e-t)}shots(){const e=this.mappings();return this.tiles.map((t,a)=>{const{shading:i,deformedNormalWeight:r,materials:s}=_r(e[a]);return{element:t.view,prepared:this.prepared[a],look:{shading:i,deformedNormalWeight:r,materials:s}}})}views(){return this.tiles.map(e=>e.view)}async create(e,t,a,i=this.size){this.events.status("making the gallery…");const r=await uf(e,t,i);this.meshId=e,this.size=r.length,this.history.add(r,null,a),this.setGeneration(this.history.current),this.events.status("")}async breed(e=Math.floor(Math.random()*2**31)){const t=this.selection.map(r=>this.mappings()[r]);if(!t.length)return;this.events.status("breeding…");const a=this.history.current,i=await xl(t,this.size??t.length,e,{mesh:this.meshId,song:this.events.songId()});this.history.add(i,a),this.setGeneration(this.history.current),this.events.status("")}showMesh(e){this.meshId=e,this.setGeneration(this.history.current);for(const t of this.restoredSelection.get(e)??[])this.toggle(t);return this.restoredSelection.delete(e),this.history.size&&(this.size=this.tileCount||this.size),this.history.size>0}snapshot(){const e={};for(const[t,a]of this.histories)a.size&&(e[t]={generations:a.generations,current:a.current,selected:t===this.meshId?this.selection:[]});return e}restore(e){for(const[t,a]of Object.entries(e)){const i=new Gh;for(const r of a.generations)i.add(r.mappings,r.parent,r.note);i.current=Math.max(0,Math.min(a.current,i.size-1)),this.histories.set(t,i),this.restoredSelection.set(t,a.selected??[])}}forget(e){this.histories.delete(e),this.restoredSelection.delete(e)}persist(){Gn({histories:this.snapshot()})}refresh(){this.prepared=this.mappings().map(e=>this.motion.prepare(e)),this.tiles.forEach((e,t)=>this.drawPlots(e,t)),this.events.requestDraw()}setGeneration(e){const t=this.history;t.current=Math.max(0,Math.min(e,t.size-1)),t.size||(t.current=-1),this.selected.clear(),this.prepared=this.motion.basis?this.mappings().map(i=>this.motion.prepare(i)):[],this.buildTiles();const a=I("generation");a.innerHTML="";for(const i of t.entries())a.add(new Option(i.label,String(i.index),!1,i.index===t.current));a.disabled=t.size<2,I("back").disabled=t.neighbour(-1)===t.current,I("forward").disabled=t.neighbour(1)===t.current,this.updateBreedButton(),this.events.requestDraw(),this.persist()}toggle(e){this.selected.has(e)?this.selected.delete(e):this.selected.add(e),this.tiles[e]?.element.classList.toggle("selected",this.selected.has(e)),this.updateBreedButton(),this.persist()}step(e){this.setGeneration(this.history.neighbour(e))}updateBreedButton(){const e=I("breed");e.disabled=this.selected.size===0,e.textContent=this.selected.size?`breed ${this.selected.size} selected`:"breed selected"}buildTiles(){const e=I("tiles");e.innerHTML="";const t=this.mappings();e.style.setProperty("--columns",String(Cl(t.length))),this.tiles=t.map((a,i)=>{const r=this.makeTile(a,i);return e.appendChild(r.element),this.drawPlots(r,i),r})}drawPlots(e,t){const a=this.prepared[t],i=this.motion.basis;!a||!i||(e.label.textContent=`#${t+1} · ${gx(gd(a))}`,ux(e.transfer,a),mx(e.amplification,a,bx(a,i.coefficients)))}makeTile(e,t){const a=document.createElement("div");return a.className="tile",a.dataset.index=String(t),a.innerHTML=`<span class="label">#${t+1}</span>
      <div class="actions"><button class="open" title="play this tile in the player"><span
        class="long">open</span><span class="short">▶</span></button>
      <button class="save" title="download this tile's mapping (JSON)"><span
        class="long">save</span><span class="short">↓</span></button></div>
      <div class="view" data-covered="${px}"></div>
      <div class="plots"><canvas class="transfer" width="160" height="34"
        title="transfer: which harmonic of the shape each sound band drives (left: low sounds, bottom: low harmonics)"></canvas>
      <canvas class="amplification" width="160" height="34"
        title="amplification: how strongly each harmonic moves with the music (up: grows, down: shrinks; coloured: reached by the music)"></canvas></div>`,a.addEventListener("click",i=>{const r=i.target;if(r.closest(".open")){this.events.open(e);return}if(r.closest(".save")){Ei(pd(e,this.motion.basis),Wa(this.events.modelName(),`g${this.history.current+1}-${t+1}`,"json"));return}this.toggle(t)}),{element:a,view:a.querySelector(".view"),label:a.querySelector(".label"),transfer:a.querySelector(".transfer"),amplification:a.querySelector(".amplification")}}}const yx=[[[" "],"play / pause"],[["Home"],"back to 0:00"],[["g","p"],"gallery, player"],[["b"],"breed the selected tiles"],[["[","]"],"previous, next generation"],[["m"],"mute"],[["l"],"loop the song"],[["f"],"full screen"],[["r"],"reset the player's view"],[["?","h"],"this help"],[["Escape"],"close"]];function Ad(n){return n.key.length===1?n.key.toLowerCase():n.key}function Td(n){if(n.ctrlKey||n.metaKey||n.altKey)return!1;const e=n.target,t=e instanceof HTMLTextAreaElement||e instanceof HTMLInputElement&&!["range","checkbox","button","file","radio"].includes(e.type),a=e instanceof HTMLInputElement&&e.type==="range";return!t&&!(a&&n.key==="Home")}function xx(n){kd(yx),document.querySelectorAll("select").forEach(e=>{e.addEventListener("change",()=>e.blur())}),window.addEventListener("keydown",e=>{if(!Td(e))return;const t=n[Ad(e)];t&&(e.preventDefault(),t())})}function wx(n){const e=t=>`<kbd>${t===" "?"space":t==="Escape"?"Esc":t.length===1?t.toUpperCase():t}</kbd>`;return n.length>2?`${e(n[0])}–${e(n[n.length-1])}`:n.map(e).join(" ")}function kd(n){const e=document.querySelector("#help table");if(e)for(const[t,a]of n){const i=document.createElement("tr");i.innerHTML=`<td>${wx(t)}</td><td></td>`,i.cells[1].textContent=a,e.append(i)}}function Rd(n){return n&&n.__esModule&&Object.prototype.hasOwnProperty.call(n,"default")?n.default:n}var ps,Hh;function Mx(){if(Hh)return ps;Hh=1;function n(e){if(this.size=e|0,this.size<=1||(this.size&this.size-1)!==0)throw new Error("FFT size must be a power of two and bigger than 1");this._csize=e<<1;for(var t=new Array(this.size*2),a=0;a<t.length;a+=2){const l=Math.PI*a/this.size;t[a]=Math.cos(l),t[a+1]=-Math.sin(l)}this.table=t;for(var i=0,r=1;this.size>r;r<<=1)i++;this._width=i%2===0?i-1:i,this._bitrev=new Array(1<<this._width);for(var s=0;s<this._bitrev.length;s++){this._bitrev[s]=0;for(var o=0;o<this._width;o+=2){var c=this._width-o-2;this._bitrev[s]|=(s>>>o&3)<<c}}this._out=null,this._data=null,this._inv=0}return ps=n,n.prototype.fromComplexArray=function(t,a){for(var i=a||new Array(t.length>>>1),r=0;r<t.length;r+=2)i[r>>>1]=t[r];return i},n.prototype.createComplexArray=function(){const t=new Array(this._csize);for(var a=0;a<t.length;a++)t[a]=0;return t},n.prototype.toComplexArray=function(t,a){for(var i=a||this.createComplexArray(),r=0;r<i.length;r+=2)i[r]=t[r>>>1],i[r+1]=0;return i},n.prototype.completeSpectrum=function(t){for(var a=this._csize,i=a>>>1,r=2;r<i;r+=2)t[a-r]=t[r],t[a-r+1]=-t[r+1]},n.prototype.transform=function(t,a){if(t===a)throw new Error("Input and output buffers must be different");this._out=t,this._data=a,this._inv=0,this._transform4(),this._out=null,this._data=null},n.prototype.realTransform=function(t,a){if(t===a)throw new Error("Input and output buffers must be different");this._out=t,this._data=a,this._inv=0,this._realTransform4(),this._out=null,this._data=null},n.prototype.inverseTransform=function(t,a){if(t===a)throw new Error("Input and output buffers must be different");this._out=t,this._data=a,this._inv=1,this._transform4();for(var i=0;i<t.length;i++)t[i]/=this.size;this._out=null,this._data=null},n.prototype._transform4=function(){var t=this._out,a=this._csize,i=this._width,r=1<<i,s=a/r<<1,o,c,l=this._bitrev;if(s===4)for(o=0,c=0;o<a;o+=s,c++){const m=l[c];this._singleTransform2(o,m,r)}else for(o=0,c=0;o<a;o+=s,c++){const m=l[c];this._singleTransform4(o,m,r)}var h=this._inv?-1:1,d=this.table;for(r>>=2;r>=2;r>>=2){s=a/r<<1;var f=s>>>2;for(o=0;o<a;o+=s)for(var b=o+f,p=o,g=0;p<b;p+=2,g+=r){const m=p,u=m+f,y=u+f,x=y+f,v=t[m],E=t[m+1],_=t[u],A=t[u+1],k=t[y],w=t[y+1],M=t[x],R=t[x+1],U=v,P=E,D=d[g],V=h*d[g+1],B=_*D-A*V,G=_*V+A*D,z=d[2*g],Y=h*d[2*g+1],te=k*z-w*Y,ie=k*Y+w*z,pe=d[3*g],Te=h*d[3*g+1],W=M*pe-R*Te,J=M*Te+R*pe,se=U+te,re=P+ie,ge=U-te,Ae=P-ie,Re=B+W,We=G+J,Ie=h*(B-W),Ke=h*(G-J),F=se+Re,vt=re+We,je=se-Re,Oe=re-We,Ee=ge+Ke,Ze=Ae-Ie,_e=ge-Ke,C=Ae+Ie;t[m]=F,t[m+1]=vt,t[u]=Ee,t[u+1]=Ze,t[y]=je,t[y+1]=Oe,t[x]=_e,t[x+1]=C}}},n.prototype._singleTransform2=function(t,a,i){const r=this._out,s=this._data,o=s[a],c=s[a+1],l=s[a+i],h=s[a+i+1],d=o+l,f=c+h,b=o-l,p=c-h;r[t]=d,r[t+1]=f,r[t+2]=b,r[t+3]=p},n.prototype._singleTransform4=function(t,a,i){const r=this._out,s=this._data,o=this._inv?-1:1,c=i*2,l=i*3,h=s[a],d=s[a+1],f=s[a+i],b=s[a+i+1],p=s[a+c],g=s[a+c+1],m=s[a+l],u=s[a+l+1],y=h+p,x=d+g,v=h-p,E=d-g,_=f+m,A=b+u,k=o*(f-m),w=o*(b-u),M=y+_,R=x+A,U=v+w,P=E-k,D=y-_,V=x-A,B=v-w,G=E+k;r[t]=M,r[t+1]=R,r[t+2]=U,r[t+3]=P,r[t+4]=D,r[t+5]=V,r[t+6]=B,r[t+7]=G},n.prototype._realTransform4=function(){var t=this._out,a=this._csize,i=this._width,r=1<<i,s=a/r<<1,o,c,l=this._bitrev;if(s===4)for(o=0,c=0;o<a;o+=s,c++){const ue=l[c];this._singleRealTransform2(o,ue>>>1,r>>>1)}else for(o=0,c=0;o<a;o+=s,c++){const ue=l[c];this._singleRealTransform4(o,ue>>>1,r>>>1)}var h=this._inv?-1:1,d=this.table;for(r>>=2;r>=2;r>>=2){s=a/r<<1;var f=s>>>1,b=f>>>1,p=b>>>1;for(o=0;o<a;o+=s)for(var g=0,m=0;g<=p;g+=2,m+=r){var u=o+g,y=u+b,x=y+b,v=x+b,E=t[u],_=t[u+1],A=t[y],k=t[y+1],w=t[x],M=t[x+1],R=t[v],U=t[v+1],P=E,D=_,V=d[m],B=h*d[m+1],G=A*V-k*B,z=A*B+k*V,Y=d[2*m],te=h*d[2*m+1],ie=w*Y-M*te,pe=w*te+M*Y,Te=d[3*m],W=h*d[3*m+1],J=R*Te-U*W,se=R*W+U*Te,re=P+ie,ge=D+pe,Ae=P-ie,Re=D-pe,We=G+J,Ie=z+se,Ke=h*(G-J),F=h*(z-se),vt=re+We,je=ge+Ie,Oe=Ae+F,Ee=Re-Ke;if(t[u]=vt,t[u+1]=je,t[y]=Oe,t[y+1]=Ee,g===0){var Ze=re-We,_e=ge-Ie;t[x]=Ze,t[x+1]=_e;continue}if(g!==p){var C=Ae,S=-Re,H=re,Q=-ge,ee=-h*F,Z=-h*Ke,ve=-h*Ie,ce=-h*We,be=C+ee,Ge=S+Z,ae=H+ce,me=Q-ve,Se=o+b-g,ke=o+f-g;t[Se]=be,t[Se+1]=Ge,t[ke]=ae,t[ke+1]=me}}}},n.prototype._singleRealTransform2=function(t,a,i){const r=this._out,s=this._data,o=s[a],c=s[a+i],l=o+c,h=o-c;r[t]=l,r[t+1]=0,r[t+2]=h,r[t+3]=0},n.prototype._singleRealTransform4=function(t,a,i){const r=this._out,s=this._data,o=this._inv?-1:1,c=i*2,l=i*3,h=s[a],d=s[a+i],f=s[a+c],b=s[a+l],p=h+f,g=h-f,m=d+b,u=o*(d-b),y=p+m,x=g,v=-u,E=p-m,_=g,A=u;r[t]=y,r[t+1]=0,r[t+2]=x,r[t+3]=v,r[t+4]=E,r[t+5]=0,r[t+6]=_,r[t+7]=A},ps}var _x=Mx();const Qo=Rd(_x);function Ex(n){const e=66.66666666666667,t=1e3,a=t/e,i=Math.log(6.4)/27;return n>=t?a+Math.log(n/t)/i:n/e}function Sx(n){const e=66.66666666666667,t=1e3,a=t/e,i=Math.log(6.4)/27;return n>=a?t*Math.exp(i*(n-a)):e*n}function Cd(n,e,t=mt.onset.mel_bands){const a=Math.min(mt.onset.mel_fmax,n/2),i=Ex(a),r=Float64Array.from({length:t+2},(c,l)=>Sx(l*i/(t+1))),s=e/2+1,o=[];for(let c=0;c<t;c++){const l=r[c+1]-r[c],h=r[c+2]-r[c+1],d=2/(r[c+2]-r[c]),f=[];let b=-1;for(let p=0;p<s;p++){const g=p*n/e,m=Math.max(0,Math.min((g-r[c])/l,(r[c+2]-g)/h));m>0&&(b<0&&(b=p),f.length=p-b,f.push(m*d))}o.push({first:Math.max(b,0),weights:Float64Array.from(f,p=>p||0),centre:r[c+1]})}return o}function Id(n,e,t){const a=Math.max(0,Math.min(e-n.start,n.held));if(n.buffer.copyWithin(0,a,n.held),n.held-=a,n.start+=a,n.held+t>n.buffer.length){const i=new Float32Array(2*(n.held+t));i.set(n.buffer.subarray(0,n.held)),n.buffer=i}}const Ta=mt.onset.beat_sample_rate/mt.onset.beat_hop,Ax=2048/mt.onset.beat_sample_rate,Tx=80,kx=1e-10,Rx=30;class Cx{constructor(e){this.sampleRate=e;const t=this.length=Math.round(Ax*e);this.half=Math.floor(t/2);const a=2**Math.ceil(Math.log2(t));this.fft=new Qo(a),this.window=Float64Array.from({length:t},(r,s)=>.5-.5*Math.cos(2*Math.PI*s/t)),this.input=new Float64Array(a),this.spectrum=this.fft.createComplexArray(),this.power=new Float64Array(a/2+1);const i=mt.onset.beat_sample_rate/2048;this.scale=(2048/t)**2*(e/a/i),this.mel=Cd(e,a),this.level=new Float64Array(this.mel.length),this.rise=new Float64Array(this.mel.length),this.buffer=new Float32Array(4*a),this.held=this.half,this.start=-this.half}sampleRate;length;half;fft;window;input;spectrum;power;mel;previous=null;level;rise;loudest=Rx;scale;buffer;held;start;next=0;centre(e){return Math.floor(e*this.sampleRate/Ta+.5)}push(e){this.held+e.length>this.buffer.length&&this.compact(e.length),this.buffer.set(e,this.held),this.held+=e.length;const t=[];for(;;){const a=this.centre(this.next);if(a-this.half+this.length>this.start+this.held)break;t.push(this.analyse(a-this.half-this.start)),this.next++}return t}compact(e){Id(this,this.centre(this.next)-this.half,e)}analyse(e){const{input:t,window:a,spectrum:i,power:r,level:s}=this;t.fill(0);for(let h=0;h<this.length;h++)t[h]=this.buffer[e+h]*a[h];this.fft.realTransform(i,t);for(let h=0;h<r.length;h++)r[h]=(i[2*h]**2+i[2*h+1]**2)*this.scale;for(let h=0;h<this.mel.length;h++){const{first:d,weights:f}=this.mel[h];let b=0;for(let p=0;p<f.length;p++)b+=f[p]*r[d+p];s[h]=10*Math.log10(Math.max(b,kx)),this.loudest=Math.max(this.loudest,s[h])}const o=this.loudest-Tx;for(let h=0;h<s.length;h++)s[h]=Math.max(s[h],o);let c=0,l=0;if(this.previous){for(let f=0;f<s.length;f++)this.rise[f]=Math.max(0,s[f]-Math.max(this.previous[f],o)),l+=this.rise[f]/s.length;const h=this.rise.slice().sort(),d=h.length;c=d%2?h[(d-1)/2]:(h[d/2-1]+h[d/2])/2,this.previous.set(s)}else this.previous=Float64Array.from(s);return[c,l]}}const Dt=mt.rate,_o=mt.bands;function Pd(n){return 2**Math.max(0,Math.ceil(Math.log2(mt.window_seconds*n)))}function Dd(n,e=_o){const t=mt.fmin,a=Math.min(mt.fmax,n/2),i=Float64Array.from({length:e+1},(r,s)=>10**(Math.log10(t)+s*(Math.log10(a)-Math.log10(t))/e));return i[0]=t,i[e]=a,i}class Vh{constructor(e){this.sampleRate=e;const t=this.N=Pd(e);this.half=t/2;const a=Float64Array.from({length:t},(o,c)=>.5-.5*Math.cos(2*Math.PI*c/t)),i=a.reduce((o,c)=>o+c,0);this.window=a.map(o=>o*2/i),this.fft=new Qo(t),this.spectrum=this.fft.createComplexArray(),this.input=new Float64Array(t),this.magnitude=new Float64Array(t/2+1),this.edges=Dd(e);const r=this.edges.length-1,s=o=>Math.ceil(o*t/e-1e-9);this.binStart=new Int32Array(r),this.binStop=new Int32Array(r),this.interpBelow=new Int32Array(r),this.interpWeight=new Float64Array(r);for(let o=0;o<r;o++){this.binStart[o]=s(this.edges[o]),this.binStop[o]=s(this.edges[o+1]);const c=Math.sqrt(this.edges[o]*this.edges[o+1]),l=Math.floor(c*t/e);this.interpBelow[o]=l,this.interpWeight[o]=c*t/e-l}this.memory=Math.exp(-1/(Dt*mt.smoothing)),this.state=new Float64Array(r),this.mel=Cd(e,t),this.beat=new Cx(e),this.lag=Math.max(1,Math.round(mt.onset.lag*Dt)),this.history=Array.from({length:this.lag},()=>new Float64Array(this.mel.length).fill(mt.onset.floor_db)),this.buffer=new Float32Array(2*t+4096),this.start=-this.half,this.held=this.half}sampleRate;N;edges;half;window;fft;spectrum;input;magnitude;binStart;binStop;interpBelow;interpWeight;memory;state;mel;beat;beatValues=[];lag;history;buffer;held=0;start=0;next=0;centre(e){return Math.floor(e*this.sampleRate/Dt+.5)}push(e){this.held+e.length>this.buffer.length&&this.compact(e.length),this.buffer.set(e,this.held),this.held+=e.length,this.beatValues.push(...this.beat.push(e));const t=[],a=this.start+this.held;for(;;){const i=this.centre(this.next);if(i+this.half>a)break;t.push(this.analyse(this.next,i)),this.next++}return t}compact(e){Id(this,this.centre(this.next)-this.half,e)}analyse(e,t){const{N:a,input:i,window:r,magnitude:s,spectrum:o}=this,c=t-this.half-this.start;for(let p=0;p<a;p++)i[p]=this.buffer[c+p]*r[p];this.fft.realTransform(o,i);for(let p=0;p<=a/2;p++)s[p]=Math.hypot(o[2*p],o[2*p+1]);const l=this.state.length,h=new Float32Array(l),d=mt.floor_db;for(let p=0;p<l;p++){let g=0;if(this.binStop[p]>this.binStart[p])for(let y=this.binStart[p];y<this.binStop[p];y++)g=Math.max(g,s[y]);else{const y=this.interpBelow[p],x=this.interpWeight[p];g=s[y]*(1-x)+s[y+1]*x}const m=20*Math.log10(Math.max(g,1e-30)),u=Math.min(1,Math.max(0,(m-d)/-d));this.state[p]=this.memory*this.state[p]+(1-this.memory)*u,h[p]=this.state[p]}const f=this.onsetStrength(),b=this.beatValues;return this.beatValues=[],{index:e,centre:t,values:h,onset:f,beat:b}}onsetStrength(){const e=this.history.shift(),t=Float64Array.from(e);let a=0;for(let i=0;i<this.mel.length;i++){const{first:r,weights:s}=this.mel[i];let o=0;for(let l=0;l<s.length;l++)o+=s[l]*this.magnitude[r+l]**2;e[i]=Math.max(10*Math.log10(Math.max(o,1e-30)),mt.onset.floor_db);const c=Math.max(0,e[i]-t[i]);a+=c}return this.history.push(e),a/this.mel.length}}const Ix=Math.floor(.03*Ta),Px=Math.floor(0*Ta)+1,Dx=Math.floor(.1*Ta),Wh=Math.floor(.1*Ta)+1,Nx=Math.floor(.03*Ta),Ux=.07,Fx=2,Vt=2*Math.floor(Math.floor(mt.onset.tempo_window*Ta)/2),Lx=120,jx=320,Ox=25,ni=4,zx=6,La=1024;class Bx{onsets=[];beats=[];tempo=0;envelope=new Float64Array(La);count=0;strength=new Float64Array(La);strengthCount=Fx;largest=0;lastOnset=-1/0;gram=new Float64Array(Vt);gramFrames=0;pooled=new Float64Array(2*Vt);pooledCount=0;fft=new Qo(2**Math.ceil(Math.log2(2*Vt)));fftInput=new Float64Array(this.fft.size);fftSpectrum=this.fft.createComplexArray();fftPower=this.fft.createComplexArray();fftOut=this.fft.createComplexArray();window=Float64Array.from({length:Vt},(e,t)=>.5-.5*Math.cos(2*Math.PI*t/Vt));push(e,t=[]){const a=this.count++;this.envelope[a%La]=e;let i=!1;for(const[r,s]of t){this.addBeatValue(r);const o=this.strengthCount++;this.strength[o%La]=s,this.largest=Math.max(this.largest,s),i=this.pickPeak(o-Wh+1)||i}return a%Ox===0&&this.pooledCount&&(this.tempo=this.estimateTempo()),this.tempo>0&&(i=this.predictBeat(a)||i),i}addBeatValue(e){const t=this.pooledCount++;this.pooled[t%this.pooled.length]=e,t>=Vt/2&&t%ni===0&&this.addToTempogram(t-Vt/2)}pooledAt(e){return e<0||e>=this.pooledCount||e<=this.pooledCount-this.pooled.length?0:this.pooled[e%this.pooled.length]}at(e){return e<0||e>=this.count||e<=this.count-La?0:this.envelope[e%La]}strengthAt(e){return e<0||e>=this.strengthCount||e<=this.strengthCount-La?0:this.strength[e%La]}pickPeak(e){if(e<0||!(this.largest>0))return!1;const t=s=>this.strengthAt(s)/this.largest,a=t(e);for(let s=Math.max(0,e-Ix);s<e+Px;s++)if(t(s)>a)return!1;let i=0,r=0;for(let s=Math.max(0,e-Dx);s<Math.min(this.strengthCount,e+Wh);s++)i+=t(s),r++;return a<i/r+Ux||e-this.lastOnset<=Nx?!1:(this.lastOnset=e,this.onsets.push(e/Ta),!0)}addColumn(e,t){const a=this.fftInput;a.fill(0);for(let c=0;c<Vt;c++)a[c]=this.pooledAt(e-Vt/2+c)*this.window[c];const i=this.fftSpectrum,r=this.fftPower,s=this.fftOut;this.fft.realTransform(i,a),this.fft.completeSpectrum(i);for(let c=0;c<i.length;c+=2)r[c]=i[c]**2+i[c+1]**2,r[c+1]=0;this.fft.inverseTransform(s,r);const o=s[0];if(!(o>0))return!1;for(let c=0;c<Vt;c++)t[c]+=s[2*c]/o;return!0}addToTempogram(e){this.addColumn(e,this.gram)&&this.gramFrames++}estimateTempo(){const e=Float64Array.from(this.gram);let t=this.gramFrames;const a=Math.max(0,this.pooledCount-Vt/2);for(let s=a+(ni-a%ni)%ni;s<this.pooledCount;s+=ni)this.addColumn(s,e)&&t++;if(!t)return 0;let i=-1/0,r=0;for(let s=1;s<Vt;s++){const o=60*Ta/s;if(o>=jx)continue;const c=-.5*(Math.log2(o)-Math.log2(Lx))**2,l=Math.log1p(1e6*(e[s]/t))+c;l>i&&(i=l,r=o)}return r}predictBeat(e){const t=60*Dt/this.tempo,a=this.beats.length?this.beats[this.beats.length-1]*Dt:-1/0;if(e-a<.6*t)return!1;const i=Math.min(zx*Dt,e);let r=0,s=-1;for(let l=0;l<t;l+=1){let h=0;for(let d=e-l;d>e-i;d-=t){const f=Math.round(d);h+=Math.max(this.at(f),this.at(f-1),this.at(f+1))}h>s&&(s=h,r=l)}if(!(s>0))return!1;const o=e-r+t,c=r<=1?e-r:o;return c>e+1||c-a<.6*t?!1:(this.beats.push(Math.max(c,e-1)/Dt),!0)}}const qh=1800,gs=60*Dt;class Gx{constructor(e,t){this.name=e,this.spectrum={name:e,rate:Dt,frames:1,bands:_o,duration:0,times:new Float32Array(gs),values:new Float32Array(gs*_o),bandEdges:Float32Array.from(Dd(t)),beats:new Float32Array(0),onsets:new Float32Array(0),downbeats:new Float32Array(0),sections:new Float32Array(0),tempo:0,meter:0,live:!0,revision:0,onsetStrength:new Float32Array(gs)}}name;spectrum;rhythm=new Bx;get seconds(){return this.spectrum.duration}get full(){return this.spectrum.frames>=qh*Dt}add(e){const t=this.spectrum;let a=!1;for(const i of e){const r=i.index;if(r>=qh*Dt)break;r>=t.times.length&&this.grow(2*t.times.length),t.values.set(i.values,r*t.bands),t.times[r]=r/Dt,t.onsetStrength[r]=i.onset,t.frames=Math.max(t.frames,r+1),a=this.rhythm.push(i.onset,i.beat)||a}t.duration=(t.frames-1)/Dt,a&&(t.onsets=Float32Array.from(this.rhythm.onsets),t.beats=Float32Array.from(this.rhythm.beats)),t.tempo=this.rhythm.beats.length>=4?this.rhythm.tempo:0,t.revision++}grow(e){const t=this.spectrum,a=new Float32Array(e);a.set(t.times);const i=new Float32Array(e);i.set(t.onsetStrength),t.onsetStrength=i;const r=new Float32Array(e*t.bands);r.set(t.values),t.times=a,t.values=r}}const Hx=""+new URL("live-worklet.js",import.meta.url).href,Vx=2/Dt;function vs(n,e){const t=n?.name??"",a=e.kind==="tab"?"tab or system audio":"the microphone or line in";if(t==="NotAllowedError"||t==="SecurityError")return`Live input: the browser was not allowed to use ${a} (permission denied); allow it in the site's settings, or keep playing songs`;if(t==="NotFoundError"||t==="OverconstrainedError")return e.kind==="tab"?"Live input: the shared tab or screen gives no sound (tick “share audio” when choosing it)":"Live input: no audio input device was found";if(t==="NotReadableError"||t==="AbortError")return`Live input: ${a} could not be opened (in use by another program, or unplugged)`;const i=n instanceof Error?n.message:String(n);return`Live input: ${a} could not be opened (${i})`}async function Wx(){return navigator.mediaDevices?.enumerateDevices?(await navigator.mediaDevices.enumerateDevices()).filter(n=>n.kind==="audioinput"):[]}const qx=()=>!!navigator.mediaDevices?.getDisplayMedia;async function Xx(n){const e=navigator.mediaDevices;if(!e)throw Object.assign(new Error("this page is not a secure context (use localhost or https)"),{name:"TypeError"});if(n.kind==="tab"){if(!e.getDisplayMedia)throw new Error("this browser does not offer tab audio");const t=await e.getDisplayMedia({video:!0,audio:{echoCancellation:!1,noiseSuppression:!1,autoGainControl:!1}});for(const a of t.getVideoTracks())a.stop(),t.removeTrack(a);if(!t.getAudioTracks().length)throw Object.assign(new Error("no sound shared"),{name:"NotFoundError"});return t}return e.getUserMedia({audio:{deviceId:n.deviceId?{exact:n.deviceId}:void 0,echoCancellation:!1,noiseSuppression:!1,autoGainControl:!1}})}class $o{constructor(e,t,a,i,r,s){this.choice=e,this.name=t,this.context=a,this.stream=i,this.source=r,this.node=s,this.take=new Gx(t,a.sampleRate);const o=i.getAudioTracks()[0]?.getSettings();this.inputLatency=o.latency??a.baseLatency??0;const c=a.sampleRate;this.analysisDelay=(Pd(c)/2+128)/c+Vx,s.port.onmessage=l=>this.receive(l.data);for(const l of i.getAudioTracks())l.addEventListener("ended",()=>this.end(`Live input: ${t} stopped (unplugged, or its sharing ended); back to the song`))}choice;name;context;stream;source;node;take;inputLatency;analysisDelay;offset=0;stats={origin:-1,firstSound:-1,samples:0,blocks:0,busyMs:0,dropouts:0,dropoutsAt:[]};onEnded=()=>{};onFrames=()=>{};receiveMs=0;stopped=!1;static async open(e,t,a){if(!e.audioWorklet)throw new Error(vs(new Error("this page cannot run an AudioWorklet (not a secure context: use localhost or https)"),a));let i;try{i=await Xx(a)}catch(r){throw new Error(vs(r,a))}try{await e.audioWorklet.addModule(Hx),e.resume();const r=e.createMediaStreamSource(i),s=new AudioWorkletNode(e,"eigendance-live",{numberOfInputs:1,numberOfOutputs:0});r.connect(s),r.connect(t);const o=i.getAudioTracks()[0],c=a.kind==="tab"?`tab audio: ${o.label||"shared"}`:o.label||a.label||"microphone";return new $o(a,c,e,i,r,s)}catch(r){for(const s of i.getTracks())s.stop();throw new Error(vs(r,a))}}get deviceKey(){return this.choice.kind==="tab"?"tab":this.stream.getAudioTracks()[0]?.getSettings().deviceId??this.choice.deviceId??"default"}get running(){return!this.stopped}get mediaStream(){return this.stream}get playing(){return!this.stopped&&this.context.state==="running"}now(){if(this.stats.origin<0)return 0;const t=this.context.currentTime-this.stats.origin/this.context.sampleRate-this.analysisDelay-this.offset;return Math.max(0,Math.min(t,this.take.seconds))}get latency(){return this.inputLatency+this.analysisDelay+this.offset}ended(){return!1}rewind(){}stop(){if(!this.stopped){this.stopped=!0,this.node.port.postMessage("stop"),this.node.port.onmessage=null,this.node.port.close(),this.source.disconnect(),this.node.disconnect();for(const e of this.stream.getTracks())e.stop()}}end(e){this.stopped||(this.stop(),this.onEnded(e))}receive(e){if(this.stopped)return;const t=performance.now(),{frames:a,...i}=e;this.stats=i,this.take.add(a),this.receiveMs+=performance.now()-t,this.onFrames(),this.take.full&&this.end(`Live input: the take reached ${this.take.seconds.toFixed(0)} s, the most kept; choose the input again for a new take`)}}const an="live:",Xh="eigendance.latency-offset.";function Nd(n){if(!n.startsWith(an))return null;const[e,...t]=n.slice(an.length).split(":");return e==="tab"?{kind:"tab"}:t.length?{kind:"mic",deviceId:t.join(":")}:{kind:"mic"}}class Kx{constructor(e){this.host=e;const t=I("live-offset");t.addEventListener("input",()=>this.setOffset(Number(t.value)/1e3)),I("live-save").addEventListener("click",()=>{this.saveTake()}),navigator.mediaDevices?.addEventListener?.("devicechange",()=>{this.listDevices()})}host;input=null;history=[];recorder=null;chunks=[];devices=[];wasPlaying=!1;get active(){return this.input?.running??!1}fillMenu(e){e.querySelector("optgroup.live")?.remove();const t=document.createElement("optgroup");t.label="live input",t.className="live";const a=this.devices.filter(r=>r.label&&r.deviceId&&r.deviceId!=="default");t.appendChild(new Option("microphone or line in (default input)",`${an}mic`));for(const r of a)t.appendChild(new Option(`input: ${r.label}`,`${an}mic:${r.deviceId}`));if(qx()&&t.appendChild(new Option("tab or system audio",`${an}tab`)),e.appendChild(t),!this.input)return;e.value=this.menuValue(this.input.choice);const i=e.selectedOptions[0];i&&(i.textContent=`● ${this.input.name}`)}async listDevices(){try{this.devices=await Wx()}catch{this.devices=[]}this.fillMenu(I("song"))}async start(e){this.stop();const{transport:t,motion:a}=this.host;let i;try{i=await $o.open(t.audioContext,t.input,e)}catch(s){return this.host.error(wa(s)),await this.host.restoreSong(),!1}this.input=i,this.history.push(i),i.offset=this.rememberedOffset(i.deviceKey),i.onEnded=s=>{this.host.error(s),this.leave()},i.onFrames=()=>this.host.requestDraw(),a.setSpectrum(i.take.spectrum),t.follow(i),this.record(i);const r=I("live-offset");return r.value=String(Math.round(i.offset*1e3)),I("live-bar").hidden=!1,I("seek").disabled=!0,document.body.classList.add("live"),this.awaitGesture(),await this.listDevices(),this.host.status(`live: ${i.name}`),this.host.requestDraw(),!0}stop(){this.recorder&&this.recorder.state!=="inactive"&&this.recorder.stop(),this.recorder=null,this.input&&(this.input.stop(),this.input=null,this.wasPlaying=!1,this.host.transport.follow(null),I("live-bar").hidden=!0,I("seek").disabled=!1,document.body.classList.remove("live"))}async leave(){this.stop(),await this.host.restoreSong()}refresh(){const e=this.input;if(!e)return;e.playing!==this.wasPlaying&&(this.wasPlaying=e.playing,this.host.transport.onChange(e.playing));const t=e.take.spectrum,a=t.tempo>0?`${t.tempo.toFixed(0)} BPM`:"no beat",i=this.host.fps()>0?1/this.host.fps():0,r=e.latency+i,s=e.stats.firstSound<0&&e.stats.samples>e.take.spectrum.rate,o=e.stats.dropouts?`; ${e.stats.dropouts} dropouts: the input fell behind and gave silence (a busy machine or device)`:"",c=I("live-info");c.textContent=`● ${s?"silent":a} · latency ${(r*1e3).toFixed(0)} ms`,c.classList.toggle("warn",s),c.classList.toggle("dropouts",o!==""),c.title=`${e.name}: input ${(e.inputLatency*1e3).toFixed(0)} ms + analysis ${(e.analysisDelay*1e3).toFixed(0)} ms + offset ${(e.offset*1e3).toFixed(0)} ms + one frame ${(i*1e3).toFixed(0)} ms; ${t.duration.toFixed(1)} s heard${s?" (no sound yet)":""}${o}`,I("live-offset-out").textContent=`${(e.offset*1e3).toFixed(0)} ms`}setOffset(e){const t=this.input;if(t){t.offset=Math.max(0,Math.min(.5,e));try{localStorage.setItem(Xh+t.deviceKey,String(t.offset))}catch{}this.refresh()}}async saveTake(){if(!this.input||!this.recorder)return this.host.error("Live input: there is no take to save (choose a live input first)"),null;let t=0;try{await new Promise(f=>{this.recorder.addEventListener("dataavailable",()=>f(),{once:!0}),this.recorder.requestData()});const a=this.recorder.mimeType||"audio/webm",i=new Date().toISOString().slice(0,19).replace("T"," ").replace(/:/g,"-"),r=a.includes("ogg")?"ogg":"webm",s=`live take ${i}.${r}`,o=Wa("live take",i,r),c=new Blob(this.chunks,{type:a});ko(c,o);const l=performance.now(),h=()=>this.host.status(`${o} downloaded; analysing it for the song menu… ${((performance.now()-l)/1e3).toFixed(0)} s`);h(),t=window.setInterval(h,1e3);const d=await pf(c,s);return window.clearInterval(t),await this.host.songAdded(d.item.id),this.host.status(`${o} downloaded; “${s}” is in the song menu`),d.item.id}catch(a){return this.host.error(`Live input: the take could not be saved (${wa(a)})`),null}finally{window.clearInterval(t)}}async awaitGesture(){const e=this.host.transport.audioContext;if(await Promise.race([e.resume(),new Promise(a=>setTimeout(a,300))]),e.state==="running"||!this.input)return;this.host.status("live: click the page or press a key to start listening");const t=()=>{e.resume().then(()=>{this.input&&this.host.status(`live: ${this.input.name}`)})};document.addEventListener("pointerdown",t,{once:!0}),document.addEventListener("keydown",t,{once:!0})}record(e){if(this.chunks=[],typeof MediaRecorder>"u")return;const t=["audio/webm;codecs=opus","audio/ogg;codecs=opus","audio/webm"].find(a=>MediaRecorder.isTypeSupported(a));try{this.recorder=new MediaRecorder(e.mediaStream,t?{mimeType:t}:void 0),this.recorder.addEventListener("dataavailable",a=>{a.data.size&&this.chunks.push(a.data)}),this.recorder.start(1e3)}catch{this.recorder=null}}rememberedOffset(e){try{const t=Number(localStorage.getItem(Xh+e));return Number.isFinite(t)?Math.max(0,Math.min(.5,t)):0}catch{return 0}}menuValue(e){return e.kind==="tab"?`${an}tab`:`${an}mic${e.deviceId?`:${e.deviceId}`:""}`}}function Jx(n){const e=c=>c.target.value,{messages:t,transport:a,viewer:i,library:r}=n;I("mesh").addEventListener("change",c=>{const l=e(c);if(l.startsWith("rig:")){n.openRig(l.slice(4));return}t.guard("Could not show this model",async()=>{await n.showMesh(l)||t.status("")})}),I("song").addEventListener("change",c=>{const l=e(c),h=Nd(l);if(h){n.startLive(h);return}t.guard("Could not play this song",()=>n.changeSong(l))}),I("mapping-menu").addEventListener("change",c=>{const l=e(c),h=r.mappings.find(d=>d.id===l)?.name??"mapping";t.guard(`Could not open ${h}`,async()=>{n.open(await ia(`api/mappings/${l}`),h)})});for(const c of["mesh","song","mapping"])I(`remove-${c}`).addEventListener("click",()=>{Zx(n,c)});I("play").addEventListener("click",()=>n.togglePlay()),I("seek").addEventListener("input",c=>{a.seek(Number(e(c))),i.requestDraw()});const s=I("volume");s.addEventListener("input",()=>{a.volume=Number(s.value),a.muted&&ys(n)}),I("mute").addEventListener("click",()=>ys(n)),I("loop").addEventListener("click",()=>Kh(n)),a.onEnd=()=>t.hint("the song ended: ▶ plays it again (↻ repeats it)",!1);for(const c of["save-session","rig-save-session"])I(c).addEventListener("click",()=>{t.guard("Could not save the session",async()=>{const l=Jo(n.gallery.snapshot(),n.rigs.sessions.snapshot(),pi(n),fr(n));await r.refresh(),Ei(Yo(l),Wa(n.rigs.active?n.rigs.rig?.name??"":n.library.meshName,"session","json"))})});for(const c of["open-session","rig-open-session"])I(c).addEventListener("change",l=>{const h=l.target,d=h.files?.[0];h.value="",d&&t.guard(`Could not open ${d.name}`,async()=>{const f=await r.refresh(),b=_d(await d.text()),p=yd(b,f);await nx(n,p.session.song,f);const g=xd(n,p,b);n.rigs.active||n.gallery.showMesh(r.meshId),await ax(n,p.session.model,f),Gn({song:pi(n),model:fr(n)}),t.status(`${d.name}: ${g}`)})});window.addEventListener("pagehide",()=>Gn({song:pi(n),model:fr(n)}));for(const c of["reset-view","rig-reset-view"])I(c).addEventListener("click",()=>Jh(n));I("tab-gallery").addEventListener("click",()=>n.setView("gallery")),I("tab-player").addEventListener("click",()=>n.setView("player"));const o=I("size");o.addEventListener("change",()=>{n.newGallery(Number(o.value))}),window.addEventListener("resize",()=>{i.resetPlayerCamera(),i.requestDraw()}),new ResizeObserver(()=>i.requestDraw()).observe(I("tiles")),new ResizeObserver(()=>i.requestDraw()).observe(I("player-area")),xx({" ":()=>n.togglePlay(),g:()=>n.setView("gallery"),p:()=>n.setView("player"),b:()=>{t.guard("Breeding failed",()=>n.rigs.active?n.rigs.gallery.breed():n.gallery.breed())},"[":()=>n.gallery.step(-1),"]":()=>n.gallery.step(1),m:()=>ys(n),l:()=>Kh(n),r:()=>Jh(n),f:()=>Yx(),"?":()=>t.help(I("help").hidden),h:()=>t.help(I("help").hidden),Escape:()=>{t.help(!1),t.clearError()},Home:()=>{a.seek(0),i.requestDraw()}})}function Kh(n){n.transport.loop=!n.transport.loop,I("loop").setAttribute("aria-pressed",String(n.transport.loop)),I("loop").classList.toggle("on",n.transport.loop)}function Jh(n){n.shownViewer().resetPlayerCamera()}function Yx(){document.fullscreenElement?document.exitFullscreen():document.documentElement.requestFullscreen?.().catch(()=>{})}function ys(n){n.transport.muted=!n.transport.muted,I("mute").classList.toggle("muted",n.transport.muted)}async function Zx(n,e){const t=I(e==="mapping"?"mapping-menu":e),a=e==="mesh"&&t.value.startsWith("rig:");if(e==="song"&&Nd(t.value)){n.messages.status("a live input plays: choose a song in the menu to remove it");return}const i=a?t.value.slice(4):t.value,r=t.selectedOptions[0]?.textContent??`the ${e}`;await n.messages.guard(`Could not remove ${r}`,async()=>{e==="mesh"&&n.library.drop(i),await bf(a?"rig":e,i),rx(n,i);const s=await n.library.refresh();if(a||e==="mesh"&&i===n.library.meshId){const o=s.meshes.find(c=>c.id===n.library.meshId)??s.meshes[0];o&&await n.showMesh(o.id)}else e==="song"&&i===n.library.songId&&s.songs.length&&(n.transport.pause(),await n.changeSong(s.songs[0].id));n.messages.status(`${r} removed from the library`)})}(function(){var n="b9H79Tebbbe9ok9Geueu9Geub9Gbb9Gruuuuuuueu9Gvuuuuueu9Gduueu9Gluuuueu9Gvuuuuub9Gouuuuuub9Gluuuub9GiuuueuiE8AdilveoveovrrwrrrDDoDrbqqbelve9Weiiviebeoweuecj:Gdkr:PlCo9TW9T9VV95dbH9F9F939H79T9F9J9H229F9Jt9VV7bb8F9TW79O9V9Wt9FW9U9J9V9KW9wWVtW949c919M9MWV9mW4W2be8A9TW79O9V9Wt9FW9U9J9V9KW9wWVtW949c919M9MWVbd8F9TW79O9V9Wt9FW9U9J9V9KW9wWVtW949c919M9MWV9c9V919U9KbiE9TW79O9V9Wt9FW9U9J9V9KW9wWVtW949wWV79P9V9UblY9TW79O9V9Wt9FW9U9J9V9KW69U9KW949c919M9MWVbv8E9TW79O9V9Wt9FW9U9J9V9KW69U9KW949c919M9MWV9c9V919U9Kbo8A9TW79O9V9Wt9FW9U9J9V9KW69U9KW949wWV79P9V9UbrE9TW79O9V9Wt9FW9U9J9V9KW69U9KW949tWG91W9U9JWbwa9TW79O9V9Wt9FW9U9J9V9KW69U9KW949tWG91W9U9JW9c9V919U9KbDL9TW79O9V9Wt9FW9U9J9V9KWS9P2tWV9p9JtbqK9TW79O9V9Wt9FW9U9J9V9KWS9P2tWV9r919HtbkL9TW79O9V9Wt9FW9U9J9V9KWS9P2tWVT949WbxY9TW79O9V9Wt9FW9U9J9V9KWS9P2tWVJ9V29VVbmE9TW79O9V9Wt9F9V9Wt9P9T9P96W9wWVtW94J9H9J9OWbza9TW79O9V9Wt9F9V9Wt9P9T9P96W9wWVtW94J9H9J9OW9ttV9P9WbHa9TW79O9V9Wt9F9V9Wt9P9T9P96W9wWVtW94SWt9J9O9sW9T9H9WbOK9TW79O9V9Wt9F79W9Ht9P9H29t9VVt9sW9T9H9WbAl79IV9RbXDwebcekdKYq:Nf8Adbk;wadhud9:8Jjjjjbc;qw9Rgr8KjjjjbcbhwdnaeTmbabcbyd;i:I:cjbaoaocb9iEgDc:GeV86bbarc;adfcbcjdz:xjjjb8AdnaiTmbarc;adfadalz:wjjjb8Akarc;abfalfcbcbcjdal9RalcFe0Ez:xjjjb8Aarc;abfarc;adfalz:wjjjb8Aar9cb83iUar9cb83i8War9cb83iyar9cb83iaar9cb83iKar9cb83izar9cb83iwar9cb83ibcj;abal9Uc;WFbGcjdalca0Ehqdnaicd6mbavcd9imbaDTmbadcefhkaqci2gxal2hmarc;alfclfhParc;qlfceVhsarc;qofclVhzcbhHincdhOcbhAdnavci6mbar9cb83i;Ooar9cb83i;Goar9cb83i;yoar9cb83i;qoadaHfgoybbhCcbhXincbhwcbhQdninaoalfhLaoybbgKaC7aQVhQawcP0meaLhoaKhCawcefgwaXfai6mbkkcbhCarc;qofhwincwhYcwh8AdnaQaC93gocFeGgEcs0mbclh8AaEci0mbcdcbaEEh8Akdnaocw4cFeGgEcs0mbclhYaEci0mbcdcbaEEhYkaYa8AfhEawydbh3cwhYcwh8Adnaocz4cFeGg5cs0mbclh8Aa5ci0mbcdcba5Eh8AkaEa3fhEdnaocFFFFb0mbclhYaocFFF8F0mbcbcdaocjjjw6EhYkawaEa8AfaYfBdbawclfhwaCcefgCcw9hmbkaLhoaKhCaXczfgXai6mbkcbhocehwazhQinawaoaQydbarc;qofaocdtfydb6EhoaQclfhQawcefgwcw9hmbkaoclthAcihOkcbhEarc;qlfcbcjdz:xjjjb8AarcbBd;ilar9cb83i;aladh8Eaqh8Fakh3inarc;qlfadaEaEcb9h9Ral2falz:wjjjb8Aaia8Faia8F6EhadnaqaiaE9RaEaqfai6EgKcsfc9WGgoaK9nmbarc;qofaKfcbaoaK9Rz:xjjjb8AkadaEal2fhhcbhginagaAVcl4hXarc;alfagcdtfh8JaHh8Kcbh8Lina8LaHfhwdndndndndndndnagPlbedibkaKTmvahawfhoarc;qlfawfRbbhQarc;qofhwaahCinawaoRbbgYaQ9RgQcetaQcKtc8F91786bbawcefhwaoalfhoaYhQaEaCcufgC9hmbxvkkaKTmla8Kc9:Ghoa8LcitcwGh8Aarc;qlfawceVfRbbcwtarc;qlfawc9:GfRbbVhQarc;qofhwaahCinawa3aofRbbcwta8EaofRbbVgYaQ9RgQcetaQcztc8F917cFFiGa8A486bbaoalfhoawcefhwaYhQaEaCcufgC9hmbxlkkasa8Kc98GgQfhoa3aQfhYarc;qlfawc98GgQfRbbhCcwhwinaoRbbawtaCVhCaocefhoawcwfgwca9hmbxdkkaKTmdxekaKTmea8Lcith5ahaQfh8AcbhLina8ARbbhQcwhoaYhwinawRbbaotaQVhQawcefhwaocwfgoca9hmbkarc;qofaLfaQaC7aX93a5486bbaYalfhYa8Aalfh8AaQhCaLcefgLaK9hmbkka8Jydbh8AcbhLarc;qofhoincdhQcbhwinaQaoawfRbbcb9hfhQawcefgwcz9hmbkclhCcbhwinaCaoawfRbbcd0fhCawcefgwcz9hmbkcwhYcbhwinaYaoawfRbbcP0fhYawcefgwcz9hmbkaQaCaQaC6EgwaYawaY6Egwczawcz6Ea8Afh8AaoczfhoaLczfgLaK6mbka8Ja8ABdbka8Kcefh8Ka8Lcefg8Lcl9hmbkagcefggaO9hmbka8Eamfh8Ea8Faxfh8Fa3amfh3aEaxfgEai6mbkcbhocehwaPhQinawaoaQydbarc;alfaocdtfydb6EhoaQclfhQaOawcefgw9hmbkaraHcd4faAcdVaoaocdSE86bbaHclfgHal6mbkkabaefhgabcefhoalcd4g8McbaDEhkadcefh8Narc;abfceVhecbhmdndninaiam9nmearc;qofcbcjdz:xjjjb8Aagao9Rak6mdadamal2gwfhxcbhHa8Nawfhzaocbakz:xjjjbg8Fakfh3aqaiam9Ramaqfai6Egscsfgocl4cifcd4hOaoc9WGg8JThPindndndndndndndndndndnaDTmbaraHcd4fRbbgQciGPlbedlbkasTmdaxaHfhoarc;abfaHfRbbhQarc;qofhwashCinawaoRbbgYaQ9RgQcetaQcKtc8F91786bbawcefhwaoalfhoaYhQaCcufgCmbxikkasTmiaHcitcwGh8Aarc;abfaHceVfRbbcwtarc;abfaHc9:GgofRbbVhQaxaofhoarc;qofhwashCinawao8VbbgYaQ9RgQcetaQcztc8F917cFFiGa8A486bbawcefhwaoalfhoaYhQaCcufgCmbxikkaeaHc98Gg8Afhoaza8AfhYarc;abfa8AfRbbhCcwhwinaoRbbawtaCVhCaocefhoawcwfgwca9hmbkasTmdaQcl4hKaHcitcKGhEaxa8Afh8AcbhLina8ARbbhQcwhoaYhwinawRbbaotaQVhQawcefhwaocwfgoca9hmbkarc;qofaLfaQaC7aK93aE486bbaYalfhYa8Aalfh8AaQhCaLcefgLas9hmbkkaDmbcbhoxlka8JTmbcbhodninarc;qofaofgwcwf8Pibaw8Pib:e9qTmeaoczfgoa8J9pmdxbkkdnavmbcehoxikcbh8AaOhLaOhKinarc;qofa8Afgocwf8Pibhyao8Pibh8PcdhQcbhwinaQaoawfRbbcb9hfhQawcefgwcz9hmbkclhCcbhwinaCaoawfRbbcd0fhCawcefgwcz9hmbkcwhYcbhwinaYaoawfRbbcP0fhYawcefgwcz9hmbkaQaCaQaC6EgoaYaoaY6Egoczaocz6EaKfhKaocucbaya8P:e9cb9sEgwaoaw6EaLfhLa8Aczfg8Aa8J9pmdxbkka8FaHcd4fgoaoRbbcdaHcetcoGtV86bbxikdnaLas6mbaKas6mba8FaHcd4fgoaoRbbciaHcetcoGtV86bbaga39Ras6mra3arc;qofasz:wjjjbasfh3xikaLaK9phoka8FaHcd4fgwawRbbaoaHcetcoGtV86bbkaga39RaO6mla3cbaOz:xjjjbgaaOfhKdndna8JmbaPhoxekdnagaK9RcK9pmbaPhoxekaocdtc:q:G:cjbfcj:G:cjbaDEg3ydxghcetc;:FFFeGhAcuhEcuahtcu7cFeGh8Ecbh8Karc;qofhQinarc;qofa8KfhXczh8AdndndnahPDbeeeeeeedekcucbaXcwf8PibaX8Pib:e9cb9sEh8AxekcbhoaAh8Aina8Aa8EaQaofRbb9nfh8Aaocefgocz9hmbkkcih5cbhYinczhwdndndna3aYcdtfydbgLPDbeeeeeeedekcucbaXcwf8PibaX8Pib:e9cb9sEhwxekaLcetc;:FFFeGhwcuaLtcu7cFeGhCcbhoinawaCaQaofRbb9nfhwaocefgocz9hmbkkdndnawa8A6mbaLaE9hmeawa8A9hmea3a5cdtfydbcwSmekaYh5awh8AkaYcefgYci9hmbkaaa8Kco4fgoaoRbba5a8Kci4coGtV86bbdndndna3a5cdtfydbgEPDdbbbbbbbebkdncwaE9Tg5TmbcuaEtcu7hwdndnaEceSmbcbh8LaQhXinaXhoa5hYcbhCinaoRbbg8AawcFeGgLa8AaL6EaCaEtVhCaocefhoaYcufgYmbkaKaC86bbaXa5fhXaKcefhKa8La5fg8Lcz6mbxdkkcbh8LaQhXinaXhoa5hYcbhCinaoRbbg8AawcFeGgLa8AaL6EaCcetVhCaocefhoaYcufgYmbkaKaC:T9cFe:d9c:c:qj:bw9:9c:q;c1:I1e:d9c:b:c:e1z9:9ca188bbaXa5fhXaKcefhKa8La5fg8Lcz6mbkkcbhoinaKaQaofRbbgC86bbaKaCawcFeG9pfhKaocefgocz9hmbxikkdnaEceSmbinaKcb86bbaKcefhKxbkkinaKcb86bbaKcefhKxbkkaKaX8Pbw83bwaKaX8Pbb83bbaKczfhKka8Kczfg8Ka8J9pgomeaQczfhQagaK9RcK9pmbkkaoTmlaKh3aKTmlkaHcefgHal9hmbkarc;abfaxascufal2falz:wjjjb8Aasamfhma3hoa3mbkcbhwxdkdnagao9RakalfgwcKcaaDEgQawaQ0EgC9pmbcbhwxdkdnawaQ9pmbaocbaCaw9Rgwz:xjjjbawfhokaoarc;adfalz:wjjjbalfhodnaDTmbaoara8Mz:wjjjba8Mfhokaoab9Rhwxekcbhwkarc;qwf8Kjjjjbawk5babaeadaialcdcbyd;i:I:cjbz:bjjjbk9reduaecd4gdaefgicaaica0Ecj;abae9Uc;WFbGcjdaeca0Egicl4cifcd4aifae2adfabaifcufai9U2fcefkmbcbabBd;i:I:cjbk;HPeLu8Jjjjjbc;ae9Rgl8Kjjjjbcbhvdnaeaici9UgocHf6mbabcbyd;m:I:cjbgrc;GeV86bbalc;abfcFecjez:xjjjb8Aal9cu83iUal9cu83i8Wal9cu83iyal9cu83iaal9cu83iKal9cu83izal9cu83iwal9cu83ibabaefc9WfhwabcefgDaofhednaiTmbcmcsarcb9kgqEhkcbhxcbhmcbhPcbhscbhzindnaeaw9nmbcbhvxikazcufhvadaPcdtfgHydbhOaHcwfydbhAaHclfydbhCcbhXdndndninalc;abfavcsGcitfgoydlhQdndndnaoydbgoaO9hmbaQaCSmekdnaoaC9hmbaQaA9hmbaXcefhXxekaoaA9hmeaQaO9hmeaXcdfhXkaXc870mdascufhvaHaXcdtgAcxGgoyd:4:G:cjbcdtfydbhQaHaoyd:0:G:cjbcdtfydbhCaHaoyd:W:G:cjbcdtfydbhOcbhodnindnalavcsGcdtfydbaQ9hmbaohXxdkcuhXavcufhvaocefgocz9hmbkkaxaQaxSgvaXce9iaXak9oVgoGfhxdndndncbcsavEaXaoEgvcs9hmbarce9imbaQaQamaQcefamSgvEgmcefSmecmcsavEhvkaDavaAc;WeGV86bbavcs9hmeaQam9Rgvcetavc8F917hvinaecbcjeavcje6EavcFbGV86bbaecefheavcr4gvmbkaQhmxvkcPhvaDaAcPV86bbaQhmkavTmiavak9omicdhocehXazhAxlkavcufhvaXclfgXc;ab9hmbkkdnaHcecdcbaAaxSEaCaxSEcdtgvyd:W:G:cjbcdtfydbgOTaHavyd:0:G:cjbcdtfydbgCceSGaHavyd:4:G:cjbcdtfydbgQcdSGaxcb9hGaqGgLce9hmbal9cu83iUal9cu83i8Wal9cu83iyal9cu83iaal9cu83iKal9cu83izal9cu83iwal9cu83ibcbhxkcbhXascufgvhodnindnalaocsGcdtfydbaC9hmbaXhAxdkcuhAaocufhoaXcefgXcz9hmbkkcbhodnindnalavcsGcdtfydbaQ9hmbaohXxdkcuhXavcufhvaocefgocz9hmbkkaxaOaxSgKfhHdndnaAcm0mbaAcefhAxekcbcsaCaHSgvEhAaHavfhHkdndnaXcm0mbaXcefhXxekcbcsaQaHSgvEhXaHavfhHkc9:cuaKEhYcbhvaXaAcltVg8AcFeGhodndndninavc;q:G:cjbfRbbaoSmeavcefgvcz9hmbxdkkaLaOax9havcm0VVmbaDavc;WeV86bbxekaDaY86bbaea8A86bbaecefhekdnaKmbaOam9Rgvcetavc8F917hvinaecbcjeavcje6EavcFbGV86bbaecefheavcr4gvmbkaOhmkdnaAcs9hmbaCam9Rgvcetavc8F917hvinaecbcjeavcje6EavcFbGV86bbaecefheavcr4gvmbkaChmkdnaXcs9hmbaQam9Rgvcetavc8F917hvinaecbcjeavcje6EavcFbGV86bbaecefheavcr4gvmbkaQhmkalascdtfaOBdbascefcsGhvdndnaAPzbeeeeeeeeeeeeeebekalavcdtfaCBdbascdfcsGhvkdndnaXPzbeeeeeeeeeeeeeebekalavcdtfaQBdbavcefcsGhvkcihoalc;abfazcitfgXaOBdlaXaCBdbazcefcsGhAcdhXavhsaHhxxekcdhoalascdtfaQBdbcehXascefcsGhsazhAkalc;abfaAcitfgvaCBdlavaQBdbalc;abfazaXfcsGcitfgvaQBdlavaOBdbaDcefhDazaofcsGhzaPcifgPai6mbkkdnaeaw9nmbcbhvxekcbhvinaeavfavc;q:G:cjbfRbb86bbavcefgvcz9hmbkaeab9Ravfhvkalc;aef8KjjjjbavkZeeucbhddninadcefgdc8F0meaeceadt0mbkkadcrfcFeGcr9Uci2cdfabci9U2cHfkmbcbabBd;m:I:cjbk:zderu8Jjjjjbcz9Rhlcbhvdnaeaicvf6mbabcbRb;m:I:cjbc;qeV86bbal9cb83iwabcefhvabaefc98fhodnaiTmbcbhecbhrcbhwindnavao6mbcbskadawcdtfydbgDalcwfaraDae9Rgeaec8F91ge7ae9Rc507grcdtfgqydb9Rgec8E91c9:Gaecdt7arVheinavcbcjeaecje6EaecFbGV86bbavcefhvaecr4gembkaqaDBdbaDheawcefgwai9hmbkkdnavao9nmbcbskavcbBbbavab9RclfhvkavkBeeucbhddninadcefgdc8F0meaeceadt0mbkkabadcwfcFeGcr9U2cvfk:dvli99dui99ludnaeTmbcuadcetcuftcu7:Zhvdndncuaicuftcu7:ZgoJbbbZMgr:lJbbb9p9DTmbar:Ohwxekcjjjj94hwkcbhicbhDinalclfIdbgrJbbbbJbbjZalIdbgq:lar:lMalcwfIdbgk:lMgr:varJbbbb9BEgrNhxaqarNhralcxfIdbhqdndnakJbbbb9GTmbaxhkxekJbbjZar:l:tgkak:maxJbbbb9GEhkJbbjZax:l:tgxax:marJbbbb9GEhrkdndnaqJbbj:;aqJbbj:;9GEgxJbbjZaxJbbjZ9FEavNJbbbZJbbb:;aqJbbbb9GEMgq:lJbbb9p9DTmbaq:Ohmxekcjjjj94hmkdndnakJbbj:;akJbbj:;9GEgqJbbjZaqJbbjZ9FEaoNJbbbZJbbb:;akJbbbb9GEMgq:lJbbb9p9DTmbaq:OhPxekcjjjj94hPkdndnarJbbj:;arJbbj:;9GEgqJbbjZaqJbbjZ9FEaoNJbbbZJbbb:;arJbbbb9GEMgr:lJbbb9p9DTmbar:Ohsxekcjjjj94hskdndnadcl9hmbabaDfgzas86bbazcifam86bbazcdfaw86bbazcefaP86bbxekabaifgzas87ebazcofam87ebazclfaw87ebazcdfaP87ebkaicwfhiaDclfhDalczfhlaecufgembkkk;hlld99eud99eudnaeTmbdndncuaicuftcu7:ZgvJbbbZMgo:lJbbb9p9DTmbao:Ohixekcjjjj94hikaic;8FiGhrinabcofcicdalclfIdb:lalIdb:l9EgialcwfIdb:lalaicdtfIdb:l9EEgialcxfIdb:lalaicdtfIdb:l9EEgiarV87ebdndnJbbj:;JbbjZalaicdtfIdbJbbbb9DEgoalaicd7cdtfIdbJ;Zl:1ZNNgwJbbj:;awJbbj:;9GEgDJbbjZaDJbbjZ9FEavNJbbbZJbbb:;awJbbbb9GEMgw:lJbbb9p9DTmbaw:Ohqxekcjjjj94hqkabcdfaq87ebdndnalaicefciGcdtfIdbJ;Zl:1ZNaoNgwJbbj:;awJbbj:;9GEgDJbbjZaDJbbjZ9FEavNJbbbZJbbb:;awJbbbb9GEMgw:lJbbb9p9DTmbaw:Ohqxekcjjjj94hqkabaq87ebdndnaoalaicufciGcdtfIdbJ;Zl:1ZNNgoJbbj:;aoJbbj:;9GEgwJbbjZawJbbjZ9FEavNJbbbZJbbb:;aoJbbbb9GEMgo:lJbbb9p9DTmbao:Ohixekcjjjj94hikabclfai87ebabcwfhbalczfhlaecufgembkkk;uvdDue998Jjjjjbcjd9Rgo8Kjjjjbdndndnadcd4grTmbc:CucbavEhwaohdarhDinadawBdbadclfhdaDcufgDmbkavcd9hmbaeTmbarcdthqcbhkalhxinaohdaxhDarhwinadadydbgmaDydbcL4cFeGc:cufgPamaP9kEBdbaDclfhDadclfhdawcufgwmbkaxaqfhxakcefgkae9hmbxdkkaeTmekarcdthxavce9hhqcbhkindndndnaqmbarTmdc:CuhwalhdarhDinawadydbcL4cFeGc:cufgmawam9kEhwadclfhdaDcufgDmbxdkkdndndndnavPleddbdkarTmlaohdalhDarhwinadcbaDydbcL4cFeGgmc:cufgPaPam0EBdbadclfhdaDclfhDawcufgwmbxikkarTmicbhdarhDindnaladfIdbgsJbbbb9Bmbaoadfas:8cL4cFeGgwc8Aawc8A0Ec:cufBdbkadclfhdaDcufgDmbxdkkarTmdkc:CuhwkcbhdarhminawhDdnavceSmbaoadfydbhDkdndnaladfIdbgscjjj;8iaDai9RcefgPcLt9R::NJbbbZJbbb:;asJbbbb9GEMgs:lJbbb9p9DTmbas:OhDxekcjjjj94hDkabadfaDcFFFiaDcFFFi9iEcFFFrGaPcKtVBdbadclfhdamcufgmmbkkabaxfhbalaxfhlakcefgkae9hmbkkaocjdf8Kjjjjbk:Olveue99iue99iudnaeTmbceaicufthvcuaitcu7:Zhocbhradcl9hhwcbhDindndnalcwfIdbgqJbbbbaqJbbbb9GEgqJbbjZaqJbbjZ9FEaoNJbbbZMgq:lJbbb9p9DTmbaq:Ohixekcjjjj94hikdndnalIdbgqJbbbbaqJbbbb9GEgqJbbjZaqJbbjZ9FEaoNJbbbZMgq:lJbbb9p9DTmbaq:Ohdxekcjjjj94hdkadai9Rcd9TgkaifhidndnalclfIdbgqJbbbbaqJbbbb9GEgqJbbjZaqJbbjZ9FEaoNJbbbZMgq:lJbbb9p9DTmbaq:Ohdxekcjjjj94hdkadai9Rcd9ThddndnalcxfIdbgqJbbbbaqJbbbb9GEgqJbbjZaqJbbjZ9FEaoNJbbbZMgq:lJbbb9p9DTmbaq:Ohxxekcjjjj94hxkadaifhiaxce91avVhxdndnawmbabaDfgmai86bbamcifax86bbamcdfad86bbamcefak86bbxekabarfgmai87ebamcofax87ebamclfad87ebamcdfak87ebkarcwfhraDclfhDalczfhlaecufgembkkk;mqdQui998Jjjjjbc:qd9Rgv8Kjjjjbavc:Sefcbc;Kbz:xjjjb8AdnadTmbaiTmbdndnabaeSmbaehoxekavcuadcdtgradcFFFFi0Ecbyd;q:I:cjbHjjjjbbgoBd:SeavceBd:mdaoaearz:wjjjb8AkavcbBd:Oeav9cb83i:Geavc:Gefaoadaiavc:Sefz:pjjjbavyd:Gehwadci9UgDcbyd;q:I:cjbHjjjjbbheavc:Sefavyd:mdgqcdtfaeBdbavaqcefgrBd:mdaecbaDz:xjjjbhkavc:SefarcdtfcuaicdtaicFFFFi0Ecbyd;q:I:cjbHjjjjbbgxBdbavaqcdfgmBd:mdalc;ebfhPawheaxhrinaralIdbaPaeydbgscwascw6EcdtfIdbMUdbaeclfhearclfhraicufgimbkavc:SefamcdtfcuaDcdtadcFFFF970Ecbyd;q:I:cjbHjjjjbbgmBdbdnadci6mbaoheamhraDhiinaraxaeydbcdtfIdbaxaeclfydbcdtfIdbMaxaecwfydbcdtfIdbMUdbaecxfhearclfhraicufgimbkkaqcifhzalc;ebfhHavc;qbfhOavheavyd:KehAavyd:OehCcbhscbhrcbhXcehQinaehLaoarcx2fgKydbhPaKclfydbhdabaXcx2fgecwfaKcwfydbgYBdbaeclfadBdbaeaPBdbakarfce86bbaOaYBdwaOadBdlaOaPBdbamarcdtfcbBdbcih8AdnasTmbaLhiinaOa8AcdtfaiydbgeBdba8AaeaY9haeaP9haead9hGGfh8AaiclfhiascufgsmbkkaXcefhXcbhsinaCaAaKascdtfydbcdtgifydbcdtfgYheawaifgdydbgPhidnaPTmbdninaeydbarSmeaeclfheaicufgiTmdxbkkaeaYaPcdtfc98fydbBdbadadydbcufBdbkascefgsci9hmbkdndndna8ATmbcuhrJbbbbhEcbhdavyd:KehYavyd:OehKindnawaOadcdtfydbcdtgsfydbgeTmbaxasfgiIdbh3aialcuadadcs0EcdtfclfIdbaHaecwaecw6EcdtfIdbMg5Udba5a3:th5aecdthiaKaYasfydbcdtfheinamaeydbgscdtfgPa5aPIdbMg3Udba3aEaEa39DgPEhEasaraPEhraeclfheaic98fgimbkkadcefgda8A9hmbkarcu9hmekaQaD9pmeindnakaQfRbbmbaQhrxdkaDaQcefgQ9hmbxdkka8Acza8Acz6EhsaOheaLhOarcu9hmekkazTmbaqcdtavc:Seffcwfheinaeydbcbyd;u:I:cjbH:bjjjbbaec98fheazcufgzmbkkavc:qdf8Kjjjjbk:0leoucuaicdtgvaicFFFFi0Egocbyd;q:I:cjbHjjjjbbhralalyd9GgwcdtfarBdbalawcefBd9GabarBdbaocbyd;q:I:cjbHjjjjbbhralalyd9GgocdtfarBdbalaocefBd9GabarBdlcuadcdtadcFFFFi0Ecbyd;q:I:cjbHjjjjbbhralalyd9GgocdtfarBdbalaocefBd9GabarBdwabydbcbavz:xjjjb8AabydbhraehladhvinaralydbcdtfgoaoydbcefBdbalclfhlavcufgvmbkcbhvabydlglhoarhwaihDinaoavBdbaoclfhoawydbavfhvawclfhwaDcufgDmbkadci9Uhqdnadcd9nmbabydwhocbhvinaecwfydbhwaeclfydbhDalaeydbcdtfgbabydbgbcefBdbaoabcdtfavBdbalaDcdtfgDaDydbgDcefBdbaoaDcdtfavBdbalawcdtfgwawydbgwcefBdbaoawcdtfavBdbaecxfheaqavcefgv9hmbkkinalalydbarydb9RBdbarclfhralclfhlaicufgimbkkQbabaeadaic;G:G:cjbz:ojjjbkQbabaeadaic;i:H:cjbz:ojjjbk9DeeuabcFeaicdtz:xjjjbhlcbhbdnadTmbindnalaeydbcdtfgiydbcu9hmbaiabBdbabcefhbkaeclfheadcufgdmbkkabk:3vioud9:du8Jjjjjbc;Wa9Rgl8Kjjjjbcbhvalcxfcbc;Kbz:xjjjb8AalcuadcitgoadcFFFFe0Ecbyd;q:I:cjbHjjjjbbgrBdxalceBd2araeadaicezNjjjbalcuaoadcjjjjoGEcbyd;q:I:cjbHjjjjbbgwBdzadcdthednadTmbabhiinaiavBdbaiclfhiadavcefgv9hmbkkawaefhDalabBdwalawBdl9cbhqindnadTmbaq9cq9:hkarhvaDhiadheinaiav8Pibak1:NcFrG87ebavcwfhvaicdfhiaecufgembkkalclfaq:NceGcdtfydbhxalclfaq9ce98gq:NceGcdtfydbhmalc;Wbfcbcjaz:xjjjb8AaDhvadhidnadTmbinalc;Wbfav8VebcdtfgeaeydbcefBdbavcdfhvaicufgimbkkcbhvcbhiinalc;WbfavfgeydbhoaeaiBdbaoaifhiavclfgvcja9hmbkadhvdndnadTmbinalc;WbfaDamydbgicetf8VebcdtfgeaeydbgecefBdbaxaecdtfaiBdbamclfhmavcufgvmbkaq9cv9smdcbhvinabawydbcdtfavBdbawclfhwadavcefgv9hmbxdkkaq9cv9smekkcwhvcbhiinalcxfavfc98fydbcbyd;u:I:cjbH:bjjjbbaiceGheclhvcehiaeTmbkalc;Waf8Kjjjjbk:Awliuo99iud9:cbhv8Jjjjjbca9Rgocbyd:4:I:cjbBdKaocb8Pd:W:I:cjb83izaocbyd;e:I:cjbBdwaocb8Pd:8:I:cjb83ibaicd4hrdndnadmbJFFuFhwJFFuuhDJFFuuhqJFFuFhkJFFuuhxJFFuFhmxekarcdthPaehsincbhiinaoczfaifgzasaifIdbgwazIdbgDaDaw9EEUdbaoaifgzawazIdbgDaDaw9DEUdbaiclfgicx9hmbkasaPfhsavcefgvad9hmbkaoIdKhDaoIdwhwaoIdChqaoIdlhkaoIdzhxaoIdbhmkdnadTmbJbbbbJbFu9hJbbbbamax:tgmamJbbbb9DEgmakaq:tgkakam9DEgkawaD:tgwawak9DEgw:vawJbbbb9BEhwdnalmbarcdthoindndnaeclfIdbaq:tawNJbbbZMgk:lJbbb9p9DTmbak:Ohixekcjjjj94hikai:S9cC:ghHdndnaeIdbax:tawNJbbbZMgk:lJbbb9p9DTmbak:Ohixekcjjjj94hikaHai:S:ehHdndnaecwfIdbaD:tawNJbbbZMgk:lJbbb9p9DTmbak:Ohixekcjjjj94hikabaHai:T9cy:g:e83ibaeaofheabcwfhbadcufgdmbxdkkarcdthoindndnaeIdbax:tawNJbbbZMgk:lJbbb9p9DTmbak:Ohixekcjjjj94hikai:SgH9ca:gaH9cz:g9cjjj;4s:d:eaH9cFe:d:e9cF:bj;4:pj;ar:d9c:bd9:9c:p;G:d;4j:E;ar:d9cH9:9c;d;H:W:y:m:g;d;Hb:d9cv9:9c;j:KM;j:KM;j:Kd:dhOdndnaeclfIdbaq:tawNJbbbZMgk:lJbbb9p9DTmbak:Ohixekcjjjj94hikai:SgH9ca:gaH9cz:g9cjjj;4s:d:eaH9cFe:d:e9cF:bj;4:pj;ar:d9c:bd9:9c:p;G:d;4j:E;ar:d9cH9:9c;d;H:W:y:m:g;d;Hb:d9cq9:9cM;j:KM;j:KM;jl:daO:ehOdndnaecwfIdbaD:tawNJbbbZMgk:lJbbb9p9DTmbak:Ohixekcjjjj94hikabaOai:SgH9ca:gaH9cz:g9cjjj;4s:d:eaH9cFe:d:e9cF:bj;4:pj;ar:d9c:bd9:9c:p;G:d;4j:E;ar:d9cH9:9c;d;H:W:y:m:g;d;Hb:d9cC9:9c:KM;j:KM;j:KMD:d:e83ibaeaofheabcwfhbadcufgdmbkkk9teiucbcbyd;y:I:cjbgeabcifc98GfgbBd;y:I:cjbdndnabZbcztgd9nmbcuhiabad9RcFFifcz4nbcuSmekaehikaik;LeeeudndnaeabVciGTmbabhixekdndnadcz9pmbabhixekabhiinaiaeydbBdbaiclfaeclfydbBdbaicwfaecwfydbBdbaicxfaecxfydbBdbaeczfheaiczfhiadc9Wfgdcs0mbkkadcl6mbinaiaeydbBdbaeclfheaiclfhiadc98fgdci0mbkkdnadTmbinaiaeRbb86bbaicefhiaecefheadcufgdmbkkabk;aeedudndnabciGTmbabhixekaecFeGc:b:c:ew2hldndnadcz9pmbabhixekabhiinaialBdbaicxfalBdbaicwfalBdbaiclfalBdbaiczfhiadc9Wfgdcs0mbkkadcl6mbinaialBdbaiclfhiadc98fgdci0mbkkdnadTmbinaiae86bbaicefhiadcufgdmbkkabk9teiucbcbyd;y:I:cjbgeabcrfc94GfgbBd;y:I:cjbdndnabZbcztgd9nmbcuhiabad9RcFFifcz4nbcuSmekaehikaikTeeucbabcbyd;y:I:cjbge9Rcifc98GaefgbBd;y:I:cjbdnabZbcztge9nmbabae9RcFFifcz4nb8Akkk;Sddbcj:Gdk;idbbbbdbbblbbbwbbbbbbbebbbdbbblbbbwbbbbbbbbbbbbbbbbbbbebbbdbbbbbbbebbbbbbbbbbbbbbbb4:h9w9N94:P:gW:j9O:ye9Pbbbbbb:l29hZ;69:9kZ;N;76Z;rg97Z;z;o9xZ8J;B85Z;:;u9yZ;b;k9HZ:2;Z9DZ9e:l9mZ59A8KZ:r;T3Z:A:zYZ79OHZ;j4::8::Y:D9V8:bbbb9s:49:Z8R:hBZ9M9M;M8:L;z;o8:;8:PG89q;x:J878R:hQ8::M:B;e87bbbbbbjZbbjZbbjZ:E;V;N8::Y:DsZ9i;H;68:xd;R8:;h0838:;W:NoZbbbb:WV9O8:uf888:9i;H;68:9c9G;L89;n;m9m89;D8Ko8:bbbbf:8tZ9m836ZS:2AZL;zPZZ818EZ9e:lxZ;U98F8:819E;68:FFuuFFuuFFuuFFuFFFuFFFuFbc;i:IdkCebbbebbbebbbdbbb9G:rbb",e=new Uint8Array([32,0,65,2,1,106,34,33,3,128,11,4,13,64,6,253,10,7,15,116,127,5,8,12,40,16,19,54,20,9,27,255,113,17,42,67,24,23,146,148,18,14,22,45,70,69,56,114,101,21,25,63,75,136,108,28,118,29,73,115]);if(typeof WebAssembly!="object")return{supported:!1};var t,a=WebAssembly.instantiate(i(n),{}).then(function(b){t=b.instance,t.exports.__wasm_call_ctors(),t.exports.meshopt_encodeVertexVersion(1),t.exports.meshopt_encodeIndexVersion(1)});function i(b){for(var p=new Uint8Array(b.length),g=0;g<b.length;++g){var m=b.charCodeAt(g);p[g]=m>96?m-97:m>64?m-39:m+4}for(var u=0,g=0;g<b.length;++g)p[u++]=p[g]<60?e[p[g]]:(p[g]-60)*64+p[++g];return p.buffer.slice(0,u)}function r(b){if(!b)throw new Error("Assertion failed")}function s(b){return new Uint8Array(b.buffer,b.byteOffset,b.byteLength)}function o(b,p,g,m){var u=t.exports.sbrk,y=u(p.length*4),x=u(g*4),v=new Uint8Array(t.exports.memory.buffer),E=s(p);v.set(E,y),m&&m(y,y,p.length,g);var _=b(x,y,p.length,g);v=new Uint8Array(t.exports.memory.buffer);var A=new Uint32Array(g);new Uint8Array(A.buffer).set(v.subarray(x,x+g*4)),E.set(v.subarray(y,y+p.length*4)),u(y-u(0));for(var k=0;k<p.length;++k)p[k]=A[p[k]];return[A,_]}function c(b,p,g,m){var u=t.exports.sbrk,y=u(g*4),x=u(g*m),v=new Uint8Array(t.exports.memory.buffer);v.set(s(p),x),b(y,x,g,m),v=new Uint8Array(t.exports.memory.buffer);var E=new Uint32Array(g);return new Uint8Array(E.buffer).set(v.subarray(y,y+g*4)),u(y-u(0)),E}function l(b,p,g,m,u,y,x){var v=t.exports.sbrk,E=v(p),_=v(m*u),A=new Uint8Array(t.exports.memory.buffer);A.set(s(g),_);var k=b(E,p,_,m,u,y,x),w=new Uint8Array(k);return w.set(A.subarray(E,E+k)),v(E-v(0)),w}function h(b){for(var p=0,g=0;g<b.length;++g){var m=b[g];p=p<m?m:p}return p}function d(b,p){if(r(p==2||p==4),p==4)return new Uint32Array(b.buffer,b.byteOffset,b.byteLength/4);var g=new Uint16Array(b.buffer,b.byteOffset,b.byteLength/2);return new Uint32Array(g)}function f(b,p,g,m,u,y,x){var v=t.exports.sbrk,E=v(g*m),_=v(g*y),A=new Uint8Array(t.exports.memory.buffer);A.set(s(p),_),b(E,g,m,u,_,x);var k=new Uint8Array(g*m);return k.set(A.subarray(E,E+g*m)),v(E-v(0)),k}return{ready:a,supported:!0,reorderMesh:function(b,p,g){r(b instanceof Uint32Array||b instanceof Int32Array),r(!p||b.length%3==0);var m=p?g?t.exports.meshopt_optimizeVertexCacheStrip:t.exports.meshopt_optimizeVertexCache:void 0;return o(t.exports.meshopt_optimizeVertexFetchRemap,b,h(b)+1,m)},reorderPoints:function(b,p){return r(b instanceof Float32Array),r(b.length%p==0),r(p>=3),c(t.exports.meshopt_spatialSortRemap,b,b.length/p,p*4)},encodeVertexBuffer:function(b,p,g){r(g>0&&g<=256),r(g%4==0);var m=t.exports.meshopt_encodeVertexBufferBound(p,g);return l(t.exports.meshopt_encodeVertexBuffer,m,b,p,g)},encodeVertexBufferLevel:function(b,p,g,m,u){r(g>0&&g<=256),r(g%4==0),r(m>=0&&m<=3),r(u===void 0||u==0||u==1);var y=t.exports.meshopt_encodeVertexBufferBound(p,g);return l(t.exports.meshopt_encodeVertexBufferLevel,y,b,p,g,m,u===void 0?-1:u)},encodeIndexBuffer:function(b,p,g){r(g==2||g==4),r(p%3==0);var m=d(b,g),u=t.exports.meshopt_encodeIndexBufferBound(p,h(m)+1);return l(t.exports.meshopt_encodeIndexBuffer,u,m,p,4)},encodeIndexSequence:function(b,p,g){r(g==2||g==4);var m=d(b,g),u=t.exports.meshopt_encodeIndexSequenceBound(p,h(m)+1);return l(t.exports.meshopt_encodeIndexSequence,u,m,p,4)},encodeGltfBuffer:function(b,p,g,m,u){var y={ATTRIBUTES:this.encodeVertexBufferLevel,TRIANGLES:this.encodeIndexBuffer,INDICES:this.encodeIndexSequence};return r(y[m]),y[m](b,p,g,2,u===void 0?0:u)},encodeFilterOct:function(b,p,g,m){return r(g==4||g==8),r(m>=2&&m<=16),f(t.exports.meshopt_encodeFilterOct,b,p,g,m,16)},encodeFilterQuat:function(b,p,g,m){return r(g==8),r(m>=4&&m<=16),f(t.exports.meshopt_encodeFilterQuat,b,p,g,m,16)},encodeFilterExp:function(b,p,g,m,u){r(g>0&&g%4==0),r(m>=1&&m<=24);var y={Separate:0,SharedVector:1,SharedComponent:2,Clamped:3};return r(!u||u in y),f(t.exports.meshopt_encodeFilterExp,b,p,g,m,g,u?y[u]:1)},encodeFilterColor:function(b,p,g,m){return r(g==4||g==8),r(m>=2&&m<=16),f(t.exports.meshopt_encodeFilterColor,b,p,g,m,16)}}})();(function(){var n="b9H79Tebbbe8Fv9Gbb9Gvuuuuueu9Giuuub9Geueu9Giuuueuixkbeeeddddillviebeoweuecj:Gdkr;Neqo9TW9T9VV95dbH9F9F939H79T9F9J9H229F9Jt9VV7bb8A9TW79O9V9Wt9F9KW9J9V9KW9wWVtW949c919M9MWVbeY9TW79O9V9Wt9F9KW9J9V9KW69U9KW949c919M9MWVbdE9TW79O9V9Wt9F9KW9J9V9KW69U9KW949tWG91W9U9JWbiL9TW79O9V9Wt9F9KW9J9V9KWS9P2tWV9p9JtblK9TW79O9V9Wt9F9KW9J9V9KWS9P2tWV9r919HtbvL9TW79O9V9Wt9F9KW9J9V9KWS9P2tWVT949WboY9TW79O9V9Wt9F9KW9J9V9KWS9P2tWVJ9V29VVbrl79IV9Rbwq;X8:kdbk:kYi5ud9:du8Jjjjjbcjq9Rgv8Kjjjjbc9:hodnalTmbcuhoaiRbbgrc;WeGc:Ge9hmbarcsGgwce0mbc9:hoalcufadcd4cbawEgDadfgrcKcaawEgqaraq0Egk6mbaicefhxcj;abad9Uc;WFbGcjdadca0EhmaialfgPar9Rgoadfhsavaoadz:jjjjbgzceVhHcbhOdndninaeaO9nmeaPax9RaD6mdamaeaO9RaOamfgoae6EgAcsfglc9WGhCaAcethXaxaDfhiaOaeaoaeao6E9RhQalcl4cifcd4hLazcjdfaAfhKcbhYabaOad2fg8AhEaHh3incbh5dnawTmbaxaYcd4fRbbh5kcbh8Eazcjdfhqinaih8Fdndndndna5a8Ecet4ciGgoc9:fPdebdkaPa8F9RaA6mrazcjdfa8EaA2fa8FaAz:jjjjb8Aa8FaAfhixdkazcjdfa8EaA2fcbaAz:kjjjb8Aa8FhixekaPa8F9RaL6mva8FaLfhidnaCTmbaPai9RcK6mbaocdtc:q:G:cjbfcj:G:cjbawEhaczhrcbhlinargoc9Wfghaqfhrdndndndndndnaaa8Fahco4fRbbalcoG4ciGcdtfydbPDbedvivvvlvkar9cb83bwar9cb83bbxlkarcbaiRbdai8Xbb9c:c:qj:bw9:9c:q;c1:I1e:d9c:b:c:e1z9:gg9cjjjjjz:dg8J9qE86bbaqaofgrcGfcbaicdfa8J9c8N1:NfghRbbag9cjjjjjw:dg8J9qE86bbarcVfcbaha8J9c8M1:NfghRbbag9cjjjjjl:dg8J9qE86bbarc7fcbaha8J9c8L1:NfghRbbag9cjjjjjd:dg8J9qE86bbarctfcbaha8J9c8K1:NfghRbbag9cjjjjje:dg8J9qE86bbarc91fcbaha8J9c8J1:NfghRbbag9cjjjj;ab:dg8J9qE86bbarc4fcbaha8J9cg1:NfghRbbag9cjjjja:dg8J9qE86bbarc93fcbaha8J9ch1:NfghRbbag9cjjjjz:dgg9qE86bbarc94fcbahag9ca1:NfghRbbai8Xbe9c:c:qj:bw9:9c:q;c1:I1e:d9c:b:c:e1z9:gg9cjjjjjz:dg8J9qE86bbarc95fcbaha8J9c8N1:NfgiRbbag9cjjjjjw:dg8J9qE86bbarc96fcbaia8J9c8M1:NfgiRbbag9cjjjjjl:dg8J9qE86bbarc97fcbaia8J9c8L1:NfgiRbbag9cjjjjjd:dg8J9qE86bbarc98fcbaia8J9c8K1:NfgiRbbag9cjjjjje:dg8J9qE86bbarc99fcbaia8J9c8J1:NfgiRbbag9cjjjj;ab:dg8J9qE86bbarc9:fcbaia8J9cg1:NfgiRbbag9cjjjja:dg8J9qE86bbarcufcbaia8J9ch1:NfgiRbbag9cjjjjz:dgg9qE86bbaiag9ca1:NfhixikaraiRblaiRbbghco4g8Ka8KciSg8KE86bbaqaofgrcGfaiclfa8Kfg8KRbbahcl4ciGg8La8LciSg8LE86bbarcVfa8Ka8Lfg8KRbbahcd4ciGg8La8LciSg8LE86bbarc7fa8Ka8Lfg8KRbbahciGghahciSghE86bbarctfa8Kahfg8KRbbaiRbeghco4g8La8LciSg8LE86bbarc91fa8Ka8Lfg8KRbbahcl4ciGg8La8LciSg8LE86bbarc4fa8Ka8Lfg8KRbbahcd4ciGg8La8LciSg8LE86bbarc93fa8Ka8Lfg8KRbbahciGghahciSghE86bbarc94fa8Kahfg8KRbbaiRbdghco4g8La8LciSg8LE86bbarc95fa8Ka8Lfg8KRbbahcl4ciGg8La8LciSg8LE86bbarc96fa8Ka8Lfg8KRbbahcd4ciGg8La8LciSg8LE86bbarc97fa8Ka8Lfg8KRbbahciGghahciSghE86bbarc98fa8KahfghRbbaiRbigico4g8Ka8KciSg8KE86bbarc99faha8KfghRbbaicl4ciGg8Ka8KciSg8KE86bbarc9:faha8KfghRbbaicd4ciGg8Ka8KciSg8KE86bbarcufaha8KfgrRbbaiciGgiaiciSgiE86bbaraifhixdkaraiRbwaiRbbghcl4g8Ka8KcsSg8KE86bbaqaofgrcGfaicwfa8Kfg8KRbbahcsGghahcsSghE86bbarcVfa8KahfghRbbaiRbeg8Kcl4g8La8LcsSg8LE86bbarc7faha8LfghRbba8KcsGg8Ka8KcsSg8KE86bbarctfaha8KfghRbbaiRbdg8Kcl4g8La8LcsSg8LE86bbarc91faha8LfghRbba8KcsGg8Ka8KcsSg8KE86bbarc4faha8KfghRbbaiRbig8Kcl4g8La8LcsSg8LE86bbarc93faha8LfghRbba8KcsGg8Ka8KcsSg8KE86bbarc94faha8KfghRbbaiRblg8Kcl4g8La8LcsSg8LE86bbarc95faha8LfghRbba8KcsGg8Ka8KcsSg8KE86bbarc96faha8KfghRbbaiRbvg8Kcl4g8La8LcsSg8LE86bbarc97faha8LfghRbba8KcsGg8Ka8KcsSg8KE86bbarc98faha8KfghRbbaiRbog8Kcl4g8La8LcsSg8LE86bbarc99faha8LfghRbba8KcsGg8Ka8KcsSg8KE86bbarc9:faha8KfghRbbaiRbrgicl4g8Ka8KcsSg8KE86bbarcufaha8KfgrRbbaicsGgiaicsSgiE86bbaraifhixekarai8Pbw83bwarai8Pbb83bbaiczfhikdnaoaC9pmbalcdfhlaoczfhraPai9RcL0mekkaoaC6moaimexokaCmva8FTmvkaqaAfhqa8Ecefg8Ecl9hmbkdndndndnawTmbasaYcd4fRbbgociGPlbedrbkaATmdazaYfh8Fazcjdfhhcbh8EaEhaina8FRbbhraahocbhlinaoahalfRbbgqce4cbaqceG9R7arfgr86bbaoadfhoaAalcefgl9hmbkaacefhaa8Fcefh8FahaAfhha8Ecefg8Ecl9hmbxikkaATmeazaYfhaazcjdfhhcbhoceh8EaKh8FinaEaofhlaa8Vbbhrcbhoinala8FaofRbbcwtahaofRbbgqVc;:FiGce4cbaqceG9R7arfgr87bbaladfhlaQaocefgofmbka8FaXfh8FcdhoaacdfhaahaXfhha8EceGhlcbh8EalmbxdkkaATmbaocl4h8EazaYfRbbhqcwhoa3hlinalRbbaotaqVhqalcefhlaocwfgoca9hmbkcbhhaEh8FaKhainazcjdfahfRbbhrcwhoaahlinalRbbaotarVhralaAfhlaocwfgoca9hmbkara8E94aq7hqcbhoa8Fhlinalaqao486bbalcefhlaocwfgoca9hmbka8Fadfh8FaacefhaahcefghaA9hmbkkaEclfhEa3clfh3aYclfgYad6mbkaza8AaAcufad2fadz:jjjjb8AaAaOfhOaihxaimbkc9:hoxdkcbc99aPax9RakSEhoxekc9:hokavcjqf8Kjjjjbaok:bsesu8Jjjjjbc;ae9Rgv8Kjjjjbc9:hodnalaeci9UgrcHf6mbcuhoaiRbbgwc;WeGc;Ge9hmbawcsGgwce0mbavc;abfcFecjez:kjjjb8Aav9cu83iUav9cu83i8Wav9cu83iyav9cu83iaav9cu83iKav9cu83izav9cu83iwav9cu83ibaialfc9WfhDaicefgiarfhqdndnaeci9pmbaqhexekcmcsawceSEhkcbhxcbhmaqhecbhlcbhoindndnaiRbbgrc;Ve0mbavc;abfaoarcu7gPcl4fcsGcitfgwydlhsawydbhzdndnarcsGgwak9pmbavalaPfcsGcdtfydbaxawEhraxawTgHfhxxekdnaeaD9nmbc9:hoxokdndnawcsSmbcehHamawcetfcWfhrxekaecefhrae8SbbgwcFeGhPdndnawcu9mmbarhexekaecvfheaPcFbGhPcrhwdninar8SbbgHcFbGawtaPVhPaHcu9kmearcefhrawcrfgwc8J9hmbxdkkarcefhekcehHaPce4cbaPceG9R7amfhrkarhmkavc;abfaocitfgwarBdbawasBdlavalcdtfarBdbavc;abfaocefcsGcitfgwazBdbawarBdlaocdfhoaHalfhldnadcd9hmbabar87elabas87edabaz87ebabcofhbxdkabarBdwabasBdlabazBdbabcxfhbxekdnarcpe0mbavalaDarcsGfRbbgwcl4gP9RcsGcdtfydbaxcefgsaPEhravalaw9RcsGcdtfydbasaPTgzfgsawcsGgPEhwaPThPdndnadcd9hmbabaw87elabar87edabax87ebcohHxekabawBdwabarBdlabaxBdbcxhHkavalcdtfaxBdbavc;abfaocitfgOarBdbaOaxBdlavalcefglcsGcdtfarBdbavc;abfaocefcsGcitfgOawBdbaOarBdlavalazfglcsGcdtfawBdbavc;abfaocdfcsGcitfgraxBdbarawBdlaocifhoabaHfhbalaPfhlasaPfhxxekdnaeaD9nmbc9:hoxlkaxcbaeRbbgwEgHarc;:eSgrfhsawcsGhOdndnawcl4gAmbascefhzxekashzavalaA9RcsGcdtfydbhskdndnaOmbazcefhxxekazhxavalaw9RcsGcdtfydbhzkdndnarTmbaecefhrxekaecdfhrae8SbegPcFeGhwdnaPcu9kmbaecofhHawcFbGhwcrhedninar8SbbgPcFbGaetawVhwaPcu9kmearcefhraecrfgec8J9hmbkaHhrxekarcefhrkawce4cbawceG9R7amfgmhHkdndnaAcsSmbarhwxekarcefhwar8SbbgecFeGhPdnaecu9kmbarcvfhsaPcFbGhPcrhedninaw8SbbgrcFbGaetaPVhParcu9kmeawcefhwaecrfgec8J9hmbkashwxekawcefhwkaPce4cbaPceG9R7amfgmhskdndnaOcsSmbawhexekawcefheaw8SbbgrcFeGhPdnarcu9kmbawcvfhzaPcFbGhPcrhrdninae8SbbgwcFbGartaPVhPawcu9kmeaecefhearcrfgrc8J9hmbkazhexekaecefhekaPce4cbaPceG9R7amfgmhzkdndnadcd9hmbabaz87elabas87edabaH87ebcohrxekabazBdwabasBdlabaHBdbcxhrkavc;abfaocitfgwasBdbawaHBdlavalcdtfaHBdbavc;abfaocefcsGcitfgwazBdbawasBdlavalcefglcsGcdtfasBdbavc;abfaocdfcsGcitfgwaHBdbawazBdlavalaATaAcsSVfglcsGcdtfazBdbalaOTaOcsSVfhlaocifhoabarfhbkaocsGhoalcsGhlaicefgiaq6mbkkcbc99aeaDSEhokavc;aef8Kjjjjbaok:clevu8Jjjjjbcz9Rhvdnalaecvf9pmbc9:skdnaiRbbc;:eGc;qeSmbcuskav9cb83iwaicefhoaialfc98fhrdnaeTmbdnadcdSmbcbhwindnaoar6mbc9:skaocefhlao8SbbgicFeGhddndnaicu9mmbalhoxekaocvfhoadcFbGhdcrhidninal8SbbgDcFbGaitadVhdaDcu9kmealcefhlaicrfgic8J9hmbxdkkalcefhokabawcdtfadc8Etc8F91adcd47avcwfadceGcdtVglydbfgiBdbalaiBdbawcefgwae9hmbxdkkcbhwindnaoar6mbc9:skaocefhlao8SbbgicFeGhddndnaicu9mmbalhoxekaocvfhoadcFbGhdcrhidninal8SbbgDcFbGaitadVhdaDcu9kmealcefhlaicrfgic8J9hmbxdkkalcefhokabawcetfadc8Etc8F91adcd47avcwfadceGcdtVglydbfgi87ebalaiBdbawcefgwae9hmbkkcbc99aoarSEk:Lvoeue99dud99eud99dndnadcl9hmbaeTmeindndnabcdfgd8Sbb:Yab8Sbbgi:Ygl:l:tabcefgv8Sbbgo:Ygr:l:tgwJbb;:9cawawNJbbbbawawJbbbb9GgDEgq:mgkaqaicb9iEalMgwawNakaqaocb9iEarMgqaqNMM:r:vglNJbbbZJbbb:;aDEMgr:lJbbb9p9DTmbar:Ohixekcjjjj94hikadai86bbdndnaqalNJbbbZJbbb:;aqJbbbb9GEMgq:lJbbb9p9DTmbaq:Ohdxekcjjjj94hdkavad86bbdndnawalNJbbbZJbbb:;awJbbbb9GEMgw:lJbbb9p9DTmbaw:Ohdxekcjjjj94hdkabad86bbabclfhbaecufgembxdkkaeTmbindndnabclfgd8Ueb:Yab8Uebgi:Ygl:l:tabcdfgv8Uebgo:Ygr:l:tgwJb;:FSawawNJbbbbawawJbbbb9GgDEgq:mgkaqaicb9iEalMgwawNakaqaocb9iEarMgqaqNMM:r:vglNJbbbZJbbb:;aDEMgr:lJbbb9p9DTmbar:Ohixekcjjjj94hikadai87ebdndnaqalNJbbbZJbbb:;aqJbbbb9GEMgq:lJbbb9p9DTmbaq:Ohdxekcjjjj94hdkavad87ebdndnawalNJbbbZJbbb:;awJbbbb9GEMgw:lJbbb9p9DTmbaw:Ohdxekcjjjj94hdkabad87ebabcwfhbaecufgembkkk:4ioiue99dud99dud99dnaeTmbcbhiabhlindndnal8Uebgv:YgoJ:ji:1Salcof8UebgrciVgw:Y:vgDNJbbbZJbbb:;avcu9kEMgq:lJbbb9p9DTmbaq:Ohkxekcjjjj94hkkalclf8Uebhvalcdf8UebhxalarcefciGcetfak87ebdndnax:YgqaDNJbbbZJbbb:;axcu9kEMgm:lJbbb9p9DTmbam:Ohxxekcjjjj94hxkabaiarciGgkfcd7cetfax87ebdndnav:YgmaDNJbbbZJbbb:;avcu9kEMgP:lJbbb9p9DTmbaP:Ohvxekcjjjj94hvkalarcufciGcetfav87ebdndnawaw2:ZgPaPMaoaoN:taqaqN:tamamN:tgoJbbbbaoJbbbb9GE:raDNJbbbZMgD:lJbbb9p9DTmbaD:Ohrxekcjjjj94hrkalakcetfar87ebalcwfhlaiclfhiaecufgembkkk9mbdnadcd4ae2gdTmbinababydbgecwtcw91:Yaece91cjjj98Gcjjj;8if::NUdbabclfhbadcufgdmbkkk:Tvirud99eudndnadcl9hmbaeTmeindndnabRbbgiabcefgl8Sbbgvabcdfgo8Sbbgrf9R:YJbbuJabcifgwRbbgdce4adVgDcd4aDVgDcl4aDVgD:Z:vgqNJbbbZMgk:lJbbb9p9DTmbak:Ohxxekcjjjj94hxkaoax86bbdndnaraif:YaqNJbbbZMgk:lJbbb9p9DTmbak:Ohoxekcjjjj94hokalao86bbdndnavaifar9R:YaqNJbbbZMgk:lJbbb9p9DTmbak:Ohixekcjjjj94hikabai86bbdndnaDadcetGadceGV:ZaqNJbbbZMgq:lJbbb9p9DTmbaq:Ohdxekcjjjj94hdkawad86bbabclfhbaecufgembxdkkaeTmbindndnab8Vebgiabcdfgl8Uebgvabclfgo8Uebgrf9R:YJbFu9habcofgw8Vebgdce4adVgDcd4aDVgDcl4aDVgDcw4aDVgD:Z:vgqNJbbbZMgk:lJbbb9p9DTmbak:Ohxxekcjjjj94hxkaoax87ebdndnaraif:YaqNJbbbZMgk:lJbbb9p9DTmbak:Ohoxekcjjjj94hokalao87ebdndnavaifar9R:YaqNJbbbZMgk:lJbbb9p9DTmbak:Ohixekcjjjj94hikabai87ebdndnaDadcetGadceGV:ZaqNJbbbZMgq:lJbbb9p9DTmbaq:Ohdxekcjjjj94hdkawad87ebabcwfhbaecufgembkkk9teiucbcbyd:K:G:cjbgeabcifc98GfgbBd:K:G:cjbdndnabZbcztgd9nmbcuhiabad9RcFFifcz4nbcuSmekaehikaik;LeeeudndnaeabVciGTmbabhixekdndnadcz9pmbabhixekabhiinaiaeydbBdbaiclfaeclfydbBdbaicwfaecwfydbBdbaicxfaecxfydbBdbaeczfheaiczfhiadc9Wfgdcs0mbkkadcl6mbinaiaeydbBdbaeclfheaiclfhiadc98fgdci0mbkkdnadTmbinaiaeRbb86bbaicefhiaecefheadcufgdmbkkabk;aeedudndnabciGTmbabhixekaecFeGc:b:c:ew2hldndnadcz9pmbabhixekabhiinaialBdbaicxfalBdbaicwfalBdbaiclfalBdbaiczfhiadc9Wfgdcs0mbkkadcl6mbinaialBdbaiclfhiadc98fgdci0mbkkdnadTmbinaiae86bbaicefhiadcufgdmbkkabkk83dbcj:Gdk8Kbbbbdbbblbbbwbbbbbbbebbbdbbblbbbwbbbbc:K:Gdkl8W:qbb",e="b9H79TebbbeKl9Gbb9Gvuuuuueu9Giuuub9Geueuixkbbebeeddddilve9Weeeviebeoweuecj:Gdkr;Neqo9TW9T9VV95dbH9F9F939H79T9F9J9H229F9Jt9VV7bb8A9TW79O9V9Wt9F9KW9J9V9KW9wWVtW949c919M9MWVbdY9TW79O9V9Wt9F9KW9J9V9KW69U9KW949c919M9MWVblE9TW79O9V9Wt9F9KW9J9V9KW69U9KW949tWG91W9U9JWbvL9TW79O9V9Wt9F9KW9J9V9KWS9P2tWV9p9JtboK9TW79O9V9Wt9F9KW9J9V9KWS9P2tWV9r919HtbrL9TW79O9V9Wt9F9KW9J9V9KWS9P2tWVT949WbwY9TW79O9V9Wt9F9KW9J9V9KWS9P2tWVJ9V29VVbDl79IV9Rbqq:I9Dklbzik94evu8Jjjjjbcz9Rhbcbheincbhdcbhiinabcwfadfaicjuaead4ceGglE86bbaialfhiadcefgdcw9hmbkaeai86b:q:W:cjbaecitab8Piw83i:q:G:cjbaecefgecjd9hmbkk:SBlEud97dur978Jjjjjbcj;kb9Rgv8Kjjjjbc9:hodnalTmbcuhoaiRbbgrc;WeGc:Ge9hmbarcsGgwce0mbc9:hoalcufadcd4cbawEgDadfgrcKcaawEgqaraq0Egk6mbaialfgxar9RhodnadTgmmbavaoad;8qbbkaicefhPcj;abad9Uc;WFbGcjdadca0EhsdndndnadTmbaoadfhzcbhHinaeaH9nmdaxaP9RaD6miabaHad2fgOavcjdfasaeaH9RaHasfae6EgAaAcsfgoc9WGgCSEhXaPaDfhQaocl4cifcd4hLavcj;cbfaCcetfhKavcj;cbfaCci2fhYavcj;cbfaCfh8AcbhEaoc;ab6h3incbh5dnawTmbaPaEcd4fRbbh5kcbh8Eavcj;cbfh8Findndndndna5a8Ecet4ciGgoc9:fPdebdkaxaQ9RaC6mwdnaCTmbavcj;cbfa8EaC2faQaC;8qbbkaQaAfhQxdkaCTmeavcj;cbfa8EaC2fcbaC;8kbxekaxaQ9RaL6moaoclVcbawEhraQaLfhocbhidna3mbaxao9Rc;Gb6mbcbhlina8FalfhidndndndndndnaQalco4fRbbgqciGarfPDbedibledibkaipxbbbbbbbbbbbbbbbbpklbxlkaiaopbblaopbbbgaclp:meaapmbzeHdOiAlCvXoQrLgacdp:meaapmbzeHdOiAlCvXoQrLpxiiiiiiiiiiiiiiiip9oghpxiiiiiiiiiiiiiiiip8Jgap5b9cjF;8;4;W;G;ab9:9cU1:Nggcitpbi:q:G:cjbagRb:q:W:cjbggpsaap5e9cjF;8;4;W;G;ab9:9cU1:Ng8Jcitpbi:q:G:cjbp9UpmbedilvorzHOACXQLpPahaap9spklbagaoclffa8JRb:q:W:cjbfhoxikaiaopbbwaopbbbgaclp:meaapmbzeHdOiAlCvXoQrLpxssssssssssssssssp9oghpxssssssssssssssssp8Jgap5b9cjF;8;4;W;G;ab9:9cU1:Nggcitpbi:q:G:cjbagRb:q:W:cjbggpsaap5e9cjF;8;4;W;G;ab9:9cU1:Ng8Jcitpbi:q:G:cjbp9UpmbedilvorzHOACXQLpPahaap9spklbagaocwffa8JRb:q:W:cjbfhoxdkaiaopbbbpklbaoczfhoxekaiaopbbdaoRbbggcitpbi:q:G:cjbagRb:q:W:cjbggpsaoRbeg8Jcitpbi:q:G:cjbp9UpmbedilvorzHOACXQLpPpklbagaocdffa8JRb:q:W:cjbfhokdndndndndndnaqcd4ciGarfPDbedibledibkaiczfpxbbbbbbbbbbbbbbbbpklbxlkaiczfaopbblaopbbbgaclp:meaapmbzeHdOiAlCvXoQrLgacdp:meaapmbzeHdOiAlCvXoQrLpxiiiiiiiiiiiiiiiip9oghpxiiiiiiiiiiiiiiiip8Jgap5b9cjF;8;4;W;G;ab9:9cU1:Nggcitpbi:q:G:cjbagRb:q:W:cjbggpsaap5e9cjF;8;4;W;G;ab9:9cU1:Ng8Jcitpbi:q:G:cjbp9UpmbedilvorzHOACXQLpPahaap9spklbagaoclffa8JRb:q:W:cjbfhoxikaiczfaopbbwaopbbbgaclp:meaapmbzeHdOiAlCvXoQrLpxssssssssssssssssp9oghpxssssssssssssssssp8Jgap5b9cjF;8;4;W;G;ab9:9cU1:Nggcitpbi:q:G:cjbagRb:q:W:cjbggpsaap5e9cjF;8;4;W;G;ab9:9cU1:Ng8Jcitpbi:q:G:cjbp9UpmbedilvorzHOACXQLpPahaap9spklbagaocwffa8JRb:q:W:cjbfhoxdkaiczfaopbbbpklbaoczfhoxekaiczfaopbbdaoRbbggcitpbi:q:G:cjbagRb:q:W:cjbggpsaoRbeg8Jcitpbi:q:G:cjbp9UpmbedilvorzHOACXQLpPpklbagaocdffa8JRb:q:W:cjbfhokdndndndndndnaqcl4ciGarfPDbedibledibkaicafpxbbbbbbbbbbbbbbbbpklbxlkaicafaopbblaopbbbgaclp:meaapmbzeHdOiAlCvXoQrLgacdp:meaapmbzeHdOiAlCvXoQrLpxiiiiiiiiiiiiiiiip9oghpxiiiiiiiiiiiiiiiip8Jgap5b9cjF;8;4;W;G;ab9:9cU1:Nggcitpbi:q:G:cjbagRb:q:W:cjbggpsaap5e9cjF;8;4;W;G;ab9:9cU1:Ng8Jcitpbi:q:G:cjbp9UpmbedilvorzHOACXQLpPahaap9spklbagaoclffa8JRb:q:W:cjbfhoxikaicafaopbbwaopbbbgaclp:meaapmbzeHdOiAlCvXoQrLpxssssssssssssssssp9oghpxssssssssssssssssp8Jgap5b9cjF;8;4;W;G;ab9:9cU1:Nggcitpbi:q:G:cjbagRb:q:W:cjbggpsaap5e9cjF;8;4;W;G;ab9:9cU1:Ng8Jcitpbi:q:G:cjbp9UpmbedilvorzHOACXQLpPahaap9spklbagaocwffa8JRb:q:W:cjbfhoxdkaicafaopbbbpklbaoczfhoxekaicafaopbbdaoRbbggcitpbi:q:G:cjbagRb:q:W:cjbggpsaoRbeg8Jcitpbi:q:G:cjbp9UpmbedilvorzHOACXQLpPpklbagaocdffa8JRb:q:W:cjbfhokdndndndndndnaqco4arfPDbedibledibkaic8Wfpxbbbbbbbbbbbbbbbbpklbxlkaic8Wfaopbblaopbbbgaclp:meaapmbzeHdOiAlCvXoQrLgacdp:meaapmbzeHdOiAlCvXoQrLpxiiiiiiiiiiiiiiiip9oghpxiiiiiiiiiiiiiiiip8Jgap5b9cjF;8;4;W;G;ab9:9cU1:Ngicitpbi:q:G:cjbaiRb:q:W:cjbgipsaap5e9cjF;8;4;W;G;ab9:9cU1:Ngqcitpbi:q:G:cjbp9UpmbedilvorzHOACXQLpPahaap9spklbaiaoclffaqRb:q:W:cjbfhoxikaic8Wfaopbbwaopbbbgaclp:meaapmbzeHdOiAlCvXoQrLpxssssssssssssssssp9oghpxssssssssssssssssp8Jgap5b9cjF;8;4;W;G;ab9:9cU1:Ngicitpbi:q:G:cjbaiRb:q:W:cjbgipsaap5e9cjF;8;4;W;G;ab9:9cU1:Ngqcitpbi:q:G:cjbp9UpmbedilvorzHOACXQLpPahaap9spklbaiaocwffaqRb:q:W:cjbfhoxdkaic8Wfaopbbbpklbaoczfhoxekaic8WfaopbbdaoRbbgicitpbi:q:G:cjbaiRb:q:W:cjbgipsaoRbegqcitpbi:q:G:cjbp9UpmbedilvorzHOACXQLpPpklbaiaocdffaqRb:q:W:cjbfhokalc;abfhialcjefaC0meaihlaxao9Rc;Fb0mbkkdnaiaC9pmbaici4hlinaxao9RcK6mwa8FaifhqdndndndndndnaQaico4fRbbalcoG4ciGarfPDbedibledibkaqpxbbbbbbbbbbbbbbbbpkbbxlkaqaopbblaopbbbgaclp:meaapmbzeHdOiAlCvXoQrLgacdp:meaapmbzeHdOiAlCvXoQrLpxiiiiiiiiiiiiiiiip9oghpxiiiiiiiiiiiiiiiip8Jgap5b9cjF;8;4;W;G;ab9:9cU1:Nggcitpbi:q:G:cjbagRb:q:W:cjbggpsaap5e9cjF;8;4;W;G;ab9:9cU1:Ng8Jcitpbi:q:G:cjbp9UpmbedilvorzHOACXQLpPahaap9spkbbagaoclffa8JRb:q:W:cjbfhoxikaqaopbbwaopbbbgaclp:meaapmbzeHdOiAlCvXoQrLpxssssssssssssssssp9oghpxssssssssssssssssp8Jgap5b9cjF;8;4;W;G;ab9:9cU1:Nggcitpbi:q:G:cjbagRb:q:W:cjbggpsaap5e9cjF;8;4;W;G;ab9:9cU1:Ng8Jcitpbi:q:G:cjbp9UpmbedilvorzHOACXQLpPahaap9spkbbagaocwffa8JRb:q:W:cjbfhoxdkaqaopbbbpkbbaoczfhoxekaqaopbbdaoRbbggcitpbi:q:G:cjbagRb:q:W:cjbggpsaoRbeg8Jcitpbi:q:G:cjbp9UpmbedilvorzHOACXQLpPpkbbagaocdffa8JRb:q:W:cjbfhokalcdfhlaiczfgiaC6mbkkaohQaoTmoka8FaCfh8Fa8Ecefg8Ecl9hmbkdndndndnawTmbazaEcd4fRbbglciGPlbedwbkaCTmdaXaEfhlavaEfpbdbh8Kcbhoinalavcj;cbfaofpblbg8La8Aaofpblbg8MpmbzeHdOiAlCvXoQrLg8NaKaofpblbgyaYaofpblbg8PpmbzeHdOiAlCvXoQrLgIpmbezHdiOAlvCXorQLgacep9Taapxeeeeeeeeeeeeeeeeghp9op9Hp9rgaa8Kp9Ug8Kp9Abbbaladfgla8Kaaaapmlvorlvorlvorlvorp9Ug8Kp9Abbbaladfgla8KaaaapmwDqkwDqkwDqkwDqkp9Ug8Kp9Abbbaladfgla8KaaaapmxmPsxmPsxmPsxmPsp9Ug8Kp9Abbbaladfgla8Ka8NaIpmwDKYqk8AExm35Ps8E8Fgacep9Taaahp9op9Hp9rgap9Ug8Kp9Abbbaladfgla8Kaaaapmlvorlvorlvorlvorp9Ug8Kp9Abbbaladfgla8KaaaapmwDqkwDqkwDqkwDqkp9Ug8Kp9Abbbaladfgla8KaaaapmxmPsxmPsxmPsxmPsp9Ug8Kp9Abbbaladfgla8Ka8La8MpmwKDYq8AkEx3m5P8Es8Fg8Laya8PpmwKDYq8AkEx3m5P8Es8Fg8MpmbezHdiOAlvCXorQLgacep9Taaahp9op9Hp9rgap9Ug8Kp9Abbbaladfgla8Kaaaapmlvorlvorlvorlvorp9Ug8Kp9Abbbaladfgla8KaaaapmwDqkwDqkwDqkwDqkp9Ug8Kp9Abbbaladfgla8KaaaapmxmPsxmPsxmPsxmPsp9Ug8Kp9Abbbaladfgla8Ka8La8MpmwDKYqk8AExm35Ps8E8Fgacep9Taaahp9op9Hp9rgap9Ughp9Abbbaladfglahaaaapmlvorlvorlvorlvorp9Ughp9AbbbaladfglahaaaapmwDqkwDqkwDqkwDqkp9Ughp9AbbbaladfglahaaaapmxmPsxmPsxmPsxmPsp9Ug8Kp9AbbbaladfhlaoczfgoaC6mbxikkaCTmeaXaEfhlavaEfpbdbh8Kcbhoinalavcj;cbfaofpblbg8La8Aaofpblbg8MpmbzeHdOiAlCvXoQrLg8NaKaofpblbgyaYaofpblbg8PpmbzeHdOiAlCvXoQrLgIpmbezHdiOAlvCXorQLgacep:neaapxebebebebebebebebghp9op:bep9rgaa8Kp:oeg8Kp9Abbbaladfgla8Kaaaapmlvorlvorlvorlvorp:oeg8Kp9Abbbaladfgla8KaaaapmwDqkwDqkwDqkwDqkp:oeg8Kp9Abbbaladfgla8KaaaapmxmPsxmPsxmPsxmPsp:oeg8Kp9Abbbaladfgla8Ka8NaIpmwDKYqk8AExm35Ps8E8Fgacep:neaaahp9op:bep9rgap:oeg8Kp9Abbbaladfgla8Kaaaapmlvorlvorlvorlvorp:oeg8Kp9Abbbaladfgla8KaaaapmwDqkwDqkwDqkwDqkp:oeg8Kp9Abbbaladfgla8KaaaapmxmPsxmPsxmPsxmPsp:oeg8Kp9Abbbaladfgla8Ka8La8MpmwKDYq8AkEx3m5P8Es8Fg8Laya8PpmwKDYq8AkEx3m5P8Es8Fg8MpmbezHdiOAlvCXorQLgacep:neaaahp9op:bep9rgap:oeg8Kp9Abbbaladfgla8Kaaaapmlvorlvorlvorlvorp:oeg8Kp9Abbbaladfgla8KaaaapmwDqkwDqkwDqkwDqkp:oeg8Kp9Abbbaladfgla8KaaaapmxmPsxmPsxmPsxmPsp:oeg8Kp9Abbbaladfgla8Ka8La8MpmwDKYqk8AExm35Ps8E8Fgacep:neaaahp9op:bep9rgap:oeghp9Abbbaladfglahaaaapmlvorlvorlvorlvorp:oeghp9AbbbaladfglahaaaapmwDqkwDqkwDqkwDqkp:oeghp9AbbbaladfglahaaaapmxmPsxmPsxmPsxmPsp:oeg8Kp9AbbbaladfhlaoczfgoaC6mbxdkkaCTmbaXaEfhrcbhocbalcl4gl9Rc8FGhiavaEfpbdbhhinaravcj;cbfaofpblbg8Ka8Aaofpblbg8LpmbzeHdOiAlCvXoQrLg8MaKaofpblbg8NaYaofpblbgypmbzeHdOiAlCvXoQrLg8PpmbezHdiOAlvCXorQLgaaip:Reaaalp:Tep9qgaahp9rghp9Abbbaradfgrahaaaapmlvorlvorlvorlvorp9rghp9AbbbaradfgrahaaaapmwDqkwDqkwDqkwDqkp9rghp9AbbbaradfgrahaaaapmxmPsxmPsxmPsxmPsp9rghp9Abbbaradfgraha8Ma8PpmwDKYqk8AExm35Ps8E8Fgaaip:Reaaalp:Tep9qgap9rghp9Abbbaradfgrahaaaapmlvorlvorlvorlvorp9rghp9AbbbaradfgrahaaaapmwDqkwDqkwDqkwDqkp9rghp9AbbbaradfgrahaaaapmxmPsxmPsxmPsxmPsp9rghp9Abbbaradfgraha8Ka8LpmwKDYq8AkEx3m5P8Es8Fg8Ka8NaypmwKDYq8AkEx3m5P8Es8Fg8LpmbezHdiOAlvCXorQLgaaip:Reaaalp:Tep9qgap9rghp9Abbbaradfgrahaaaapmlvorlvorlvorlvorp9rghp9AbbbaradfgrahaaaapmwDqkwDqkwDqkwDqkp9rghp9AbbbaradfgrahaaaapmxmPsxmPsxmPsxmPsp9rghp9Abbbaradfgraha8Ka8LpmwDKYqk8AExm35Ps8E8Fgaaip:Reaaalp:Tep9qgap9rghp9Abbbaradfgrahaaaapmlvorlvorlvorlvorp9rghp9AbbbaradfgrahaaaapmwDqkwDqkwDqkwDqkp9rghp9AbbbaradfgrahaaaapmxmPsxmPsxmPsxmPsp9rghp9AbbbaradfhraoczfgoaC6mbkkaEclfgEad6mbkdnaXavcjdf9hmbaAad2goTmbaOavcjdfao;8qbbkdnammbavaXaAcufad2fad;8qbbkaAaHfhHc9:hoaQhPaQmbxlkkaeTmbaDalfhrcbhocuhlinaralaD9RglfaD6mdasaeao9Raoasfae6Eaofgoae6mbkaial9RhPkcbc99axaP9RakSEhoxekc9:hokavcj;kbf8Kjjjjbaokwbz:bjjjbkpPesu8Jjjjjbc;ae9Rgv8Kjjjjbc9:hodnalaeci9UgrcHf6mbcuhoaiRbbgwc;WeGc;Ge9hmbawcsGgwce0mbavc;abfcFecje;8kbav9cu83iUav9cu83i8Wav9cu83iyav9cu83iaav9cu83iKav9cu83izav9cu83iwav9cu83ibaialfc9WfhDaicefgiarfhqdndnaeci9pmbaqhexekcmcsawceSEhkcbhxcbhmaqhecbhlcbhoindndnaiRbbgrc;Ve0mbavc;abfaoarcu7gPcl4fcsGcitfgwydlhsawydbhzdndnarcsGgwak9pmbavalaPfcsGcdtfydbaxawEhraxawTgHfhxxekdnaeaD9nmbc9:hoxokdndnawcsSmbcehHamawcetfcWfhrxekaecefhrae8SbbgwcFeGhPdndnawcu9mmbarhexekaecvfheaPcFbGhPcrhwdninar8SbbgHcFbGawtaPVhPaHcu9kmearcefhrawcrfgwc8J9hmbxdkkarcefhekcehHaPce4cbaPceG9R7amfhrkarhmkavc;abfaocitfgwarBdbawasBdlavalcdtfarBdbavc;abfaocefcsGcitfgwazBdbawarBdlaocdfhoaHalfhldnadcd9hmbabar87elabas87edabaz87ebabcofhbxdkabarBdwabasBdlabazBdbabcxfhbxekdnarcpe0mbavalaDarcsGfRbbgwcl4gP9RcsGcdtfydbaxcefgsaPEhravalaw9RcsGcdtfydbasaPTgzfgsawcsGgPEhwaPThPdndnadcd9hmbabaw87elabar87edabax87ebcohHxekabawBdwabarBdlabaxBdbcxhHkavalcdtfaxBdbavc;abfaocitfgOarBdbaOaxBdlavalcefglcsGcdtfarBdbavc;abfaocefcsGcitfgOawBdbaOarBdlavalazfglcsGcdtfawBdbavc;abfaocdfcsGcitfgraxBdbarawBdlaocifhoabaHfhbalaPfhlasaPfhxxekdnaeaD9nmbc9:hoxlkaxcbaeRbbgwEgHarc;:eSgrfhsawcsGhOdndnawcl4gAmbascefhzxekashzavalaA9RcsGcdtfydbhskdndnaOmbazcefhxxekazhxavalaw9RcsGcdtfydbhzkdndnarTmbaecefhrxekaecdfhrae8SbegPcFeGhwdnaPcu9kmbaecofhHawcFbGhwcrhedninar8SbbgPcFbGaetawVhwaPcu9kmearcefhraecrfgec8J9hmbkaHhrxekarcefhrkawce4cbawceG9R7amfgmhHkdndnaAcsSmbarhwxekarcefhwar8SbbgecFeGhPdnaecu9kmbarcvfhsaPcFbGhPcrhedninaw8SbbgrcFbGaetaPVhParcu9kmeawcefhwaecrfgec8J9hmbkashwxekawcefhwkaPce4cbaPceG9R7amfgmhskdndnaOcsSmbawhexekawcefheaw8SbbgrcFeGhPdnarcu9kmbawcvfhzaPcFbGhPcrhrdninae8SbbgwcFbGartaPVhPawcu9kmeaecefhearcrfgrc8J9hmbkazhexekaecefhekaPce4cbaPceG9R7amfgmhzkdndnadcd9hmbabaz87elabas87edabaH87ebcohrxekabazBdwabasBdlabaHBdbcxhrkavc;abfaocitfgwasBdbawaHBdlavalcdtfaHBdbavc;abfaocefcsGcitfgwazBdbawasBdlavalcefglcsGcdtfasBdbavc;abfaocdfcsGcitfgwaHBdbawazBdlavalaATaAcsSVfglcsGcdtfazBdbalaOTaOcsSVfhlaocifhoabarfhbkaocsGhoalcsGhlaicefgiaq6mbkkcbc99aeaDSEhokavc;aef8Kjjjjbaok:clevu8Jjjjjbcz9Rhvdnalaecvf9pmbc9:skdnaiRbbc;:eGc;qeSmbcuskav9cb83iwaicefhoaialfc98fhrdnaeTmbdnadcdSmbcbhwindnaoar6mbc9:skaocefhlao8SbbgicFeGhddndnaicu9mmbalhoxekaocvfhoadcFbGhdcrhidninal8SbbgDcFbGaitadVhdaDcu9kmealcefhlaicrfgic8J9hmbxdkkalcefhokabawcdtfadc8Etc8F91adcd47avcwfadceGcdtVglydbfgiBdbalaiBdbawcefgwae9hmbxdkkcbhwindnaoar6mbc9:skaocefhlao8SbbgicFeGhddndnaicu9mmbalhoxekaocvfhoadcFbGhdcrhidninal8SbbgDcFbGaitadVhdaDcu9kmealcefhlaicrfgic8J9hmbxdkkalcefhokabawcetfadc8Etc8F91adcd47avcwfadceGcdtVglydbfgi87ebalaiBdbawcefgwae9hmbkkcbc99aoarSEk;Toio97eue97aec98Ghedndnadcl9hmbaeTmecbhdinababpbbbgicKp:RecKp:Sep;6eglaicwp:RecKp:Sep;6ealp;Geaiczp:RecKp:Sep;6egvp;Gep;Kep;Legopxbbbbbbbbbbbbbbbbp:2egralpxbbbjbbbjbbbjbbbjgwp9op9rp;Keglpxbb;:9cbb;:9cbb;:9cbb;:9calalp;Meaoaop;Meavaravawp9op9rp;Keglalp;Mep;Kep;Kep;Jep;Negvp;Mepxbbn0bbn0bbn0bbn0grp;KepxFbbbFbbbFbbbFbbbp9oaipxbbbFbbbFbbbFbbbFp9op9qalavp;Mearp;Kecwp:RepxbFbbbFbbbFbbbFbbp9op9qaoavp;Mearp;Keczp:RepxbbFbbbFbbbFbbbFbp9op9qpkbbabczfhbadclfgdae6mbxdkkaeTmbcbhdinabczfgDaDpbbbgipxbbbbbbFFbbbbbbFFgwp9oabpbbbgoaipmbediwDqkzHOAKY8AEgvczp:Reczp:Sep;6eglaoaipmlvorxmPsCXQL358E8FpxFubbFubbFubbFubbp9op;6eavczp:Sep;6egvp;Gealp;Gep;Kep;Legipxbbbbbbbbbbbbbbbbp:2egralpxbbbjbbbjbbbjbbbjgqp9op9rp;Keglpxb;:FSb;:FSb;:FSb;:FSalalp;Meaiaip;Meavaravaqp9op9rp;Keglalp;Mep;Kep;Kep;Jep;Negvp;Mepxbbn0bbn0bbn0bbn0grp;KepxFFbbFFbbFFbbFFbbp9oaiavp;Mearp;Keczp:Rep9qgialavp;Mearp;KepxFFbbFFbbFFbbFFbbp9oglpmwDKYqk8AExm35Ps8E8Fp9qpkbbabaoawp9oaialpmbezHdiOAlvCXorQLp9qpkbbabcafhbadclfgdae6mbkkk;2ileue97euo97dnaec98GgiTmbcbheinabcKfpx:ji:1S:ji:1S:ji:1S:ji:1SabpbbbglabczfgvpbbbgopmlvorxmPsCXQL358E8Fgrczp:Segwpxibbbibbbibbbibbbp9qp;6egDp;NegqaDaDp;MegDaDp;KealaopmbediwDqkzHOAKY8AEgDczp:Reczp:Sep;6eglalp;MeaDczp:Sep;6egoaop;Mearczp:Reczp:Sep;6egrarp;Mep;Kep;Kep;Lepxbbbbbbbbbbbbbbbbp:4ep;Jep;Mepxbbn0bbn0bbn0bbn0gDp;KepxFFbbFFbbFFbbFFbbgkp9oaqaop;MeaDp;Keczp:Rep9qgoaqalp;MeaDp;Keakp9oaqarp;MeaDp;Keczp:Rep9qgDpmwDKYqk8AExm35Ps8E8Fglp5eawclp:RegqpEi:T:j83ibavalp5baqpEd:T:j83ibabcwfaoaDpmbezHdiOAlvCXorQLgDp5eaqpEe:T:j83ibabaDp5baqpEb:T:j83ibabcafhbaeclfgeai6mbkkkuee97dnadcd4ae2c98GgeTmbcbhdinababpbbbgicwp:Recwp:Sep;6eaicep:SepxbbjFbbjFbbjFbbjFp9opxbbjZbbjZbbjZbbjZp:Uep;Mepkbbabczfhbadclfgdae6mbkkk:Sodw97euaec98Ghedndnadcl9hmbaeTmecbhdinabpxbbuJbbuJbbuJbbuJabpbbbgicKp:TeglaicYp:Tep9qgvcdp:Teavp9qgvclp:Teavp9qgop;6ep;Negvaicwp:RecKp:SegraipxFbbbFbbbFbbbFbbbgwp9ogDp:Uep;6ep;Mepxbbn0bbn0bbn0bbn0gqp;Kecwp:RepxbFbbbFbbbFbbbFbbp9oavaDarp:Xeaiczp:RecKp:Segip:Uep;6ep;Meaqp;Keawp9op9qavaDaraip:Uep:Xep;6ep;Meaqp;Keczp:RepxbbFbbbFbbbFbbbFbp9op9qavaoalcep:Rep9oalpxebbbebbbebbbebbbp9op9qp;6ep;Meaqp;KecKp:Rep9qpkbbabczfhbadclfgdae6mbxdkkaeTmbcbhdinabczfgkpxbFu9hbFu9hbFu9hbFu9habpbbbglakpbbbgrpmlvorxmPsCXQL358E8Fgvczp:TegqavcHp:Tep9qgicdp:Teaip9qgiclp:Teaip9qgicwp:Teaip9qgop;6ep;NegialarpmbediwDqkzHOAKY8AEgDpxFFbbFFbbFFbbFFbbglp9ograDczp:Segwp:Ueavczp:Reczp:SegDp:Xep;6ep;Mepxbbn0bbn0bbn0bbn0gvp;Kealp9oaiarawaDp:Uep:Xep;6ep;Meavp;Keczp:Rep9qgwaiaoaqcep:Rep9oaqpxebbbebbbebbbebbbp9op9qp;6ep;Meavp;Keczp:ReaiaDarp:Uep;6ep;Meavp;Kealp9op9qgipmwDKYqk8AExm35Ps8E8FpkbbabawaipmbezHdiOAlvCXorQLpkbbabcafhbadclfgdae6mbkkk9teiucbcbydj:G:cjbgeabcifc98GfgbBdj:G:cjbdndnabZbcztgd9nmbcuhiabad9RcFFifcz4nbcuSmekaehikaikkxebcj:Gdklz:zbb",t=new Uint8Array([0,97,115,109,1,0,0,0,1,4,1,96,0,0,3,3,2,0,0,5,3,1,0,1,12,1,0,10,22,2,12,0,65,0,65,0,65,0,252,10,0,0,11,7,0,65,0,253,15,26,11]),a=new Uint8Array([32,0,65,2,1,106,34,33,3,128,11,4,13,64,6,253,10,7,15,116,127,5,8,12,40,16,19,54,20,9,27,255,113,17,42,67,24,23,146,148,18,14,22,45,70,69,56,114,101,21,25,63,75,136,108,28,118,29,73,115]);if(typeof WebAssembly!="object")return{supported:!1};var i=WebAssembly.validate(t)?o(e):o(n),r,s=WebAssembly.instantiate(i,{}).then(function(u){r=u.instance,r.exports.__wasm_call_ctors()});function o(u){for(var y=new Uint8Array(u.length),x=0;x<u.length;++x){var v=u.charCodeAt(x);y[x]=v>96?v-97:v>64?v-39:v+4}for(var E=0,x=0;x<u.length;++x)y[E++]=y[x]<60?a[y[x]]:(y[x]-60)*64+y[++x];return y.buffer.slice(0,E)}function c(u,y,x,v,E,_,A){var k=u.exports.sbrk,w=v+3&-4,M=k(w*E),R=k(_.length),U=new Uint8Array(u.exports.memory.buffer);U.set(_,R);var P=y(M,v,E,R,_.length);if(P==0&&A&&A(M,w,E),x.set(U.subarray(M,M+v*E)),k(M-k(0)),P!=0)throw new Error("Malformed buffer data: "+P)}var l={NONE:"",OCTAHEDRAL:"meshopt_decodeFilterOct",QUATERNION:"meshopt_decodeFilterQuat",EXPONENTIAL:"meshopt_decodeFilterExp",COLOR:"meshopt_decodeFilterColor"},h={ATTRIBUTES:"meshopt_decodeVertexBuffer",TRIANGLES:"meshopt_decodeIndexBuffer",INDICES:"meshopt_decodeIndexSequence"},d=[],f=0;function b(u){var y={object:new Worker(u),pending:0,requests:{}};return y.object.onmessage=function(x){var v=x.data;y.pending-=v.count,y.requests[v.id][v.action](v.value),delete y.requests[v.id]},y}function p(u){for(var y="self.ready = WebAssembly.instantiate(new Uint8Array(["+new Uint8Array(i)+"]), {}).then(function(result) { result.instance.exports.__wasm_call_ctors(); return result.instance; });self.onmessage = "+m.name+";"+c.toString()+m.toString(),x=new Blob([y],{type:"text/javascript"}),v=URL.createObjectURL(x),E=d.length;E<u;++E)d[E]=b(v);for(var E=u;E<d.length;++E)d[E].object.postMessage({});d.length=u,URL.revokeObjectURL(v)}function g(u,y,x,v,E){for(var _=d[0],A=1;A<d.length;++A)d[A].pending<_.pending&&(_=d[A]);return new Promise(function(k,w){var M=new Uint8Array(x),R=++f;_.pending+=u,_.requests[R]={resolve:k,reject:w},_.object.postMessage({id:R,count:u,size:y,source:M,mode:v,filter:E},[M.buffer])})}function m(u){var y=u.data;self.ready.then(function(x){if(!y.id)return self.close();try{var v=new Uint8Array(y.count*y.size);c(x,x.exports[y.mode],v,y.count,y.size,y.source,x.exports[y.filter]),self.postMessage({id:y.id,count:y.count,action:"resolve",value:v},[v.buffer])}catch(E){self.postMessage({id:y.id,count:y.count,action:"reject",value:E})}})}return{ready:s,supported:!0,useWorkers:function(u){p(u)},decodeVertexBuffer:function(u,y,x,v,E){c(r,r.exports.meshopt_decodeVertexBuffer,u,y,x,v,r.exports[l[E]])},decodeIndexBuffer:function(u,y,x,v){c(r,r.exports.meshopt_decodeIndexBuffer,u,y,x,v)},decodeIndexSequence:function(u,y,x,v){c(r,r.exports.meshopt_decodeIndexSequence,u,y,x,v)},decodeGltfBuffer:function(u,y,x,v,E,_){c(r,r.exports[h[E]],u,y,x,v,r.exports[l[_]])},decodeGltfBufferAsync:function(u,y,x,v,E){return d.length>0?g(u,y,x,h[v],l[E]):s.then(function(){var _=new Uint8Array(u*y);return c(r,r.exports[h[v]],_,u,y,x,r.exports[l[E]]),_})}}})();var Pr=(function(){var n="b9H79Tebbbe;veC9Geueu9Geub9Gbb9Gsuuuuuuuuuuuu99uueu9Gvuuuuub9Gruuuuuuub9Gouuuuuue999Gvuuuuueu9Gzuuuuuuuuuuu99uuuub9Gquuuuuuu99uueu9GPuuuuuuuuuuu99uueu9Gquuuuuuuu99ueu9Gruuuuuu99eu9Gwuuuuuu99ueu9Giuuue999GDuuuuuuuuueu9Gkuuuuuuuu99uub9Gluuuueu9Gluuuub9Giuuueui3EdilvorlwDiqkrxmPszdHObAAbeAlve9Weiiviebeoweuecj:Gdkr:Sdmo9TW9T9VV95dbH9F9F939H79T9F9J9H229F9Jt9VV7bbz9TW79O9V9Wt9F79P9T9W29P9M95bw8E9TW79O9V9Wt9F79P9T9W29P9M959x9Pt9OcttV9P9I91tW7bD8A9TW79O9V9Wt9F79P9T9W29P9M959x9Pt9O9v9W9K9HtWbqQ9TW79O9V9Wt9F79P9T9W29P9M959t29V9W9W95bkX9TW79O9V9Wt9F79P9T9W29P9M959qV919UWbmQ9TW79O9V9Wt9F79P9T9W29P9M959q9V9P9Ut7bPX9TW79O9V9Wt9F79P9T9W29P9M959t9J9H2WbsP9TW79O9V9Wt9FVW9TW79Obza9TW79O9V9Wt9F9V9Wt9P9T9P96W9wWVtW94SWt9J9O9sW9T9H9WbA59TW79O9V9Wt9F9NW9UWV9HtW9q9V79Pt9P9V9U9sW9T9H9WbCl79IV9RbXDwebcekdKYq:p:1dElbzOk:Q:tekYue99iuQ99eui99Due99xue9:w998Jjjjjbcj;sb9Rgs8Kjjjjbcbhzasc:Cefcbc;Kbz:xjjjb8AdnabaeSmbabaeadcdtz:wjjjb8AkdnamcdGTmbalcrfci4cbyd;y:L:cjbHjjjjbbhHasc:Cefasyd;8egecdtfaHBdbasaecefBd;8ecbhlcbhednadTmbabheadhOinaHaeydbci4fcb86bbaeclfheaOcufgOmbkcbhlabheadhOinaHaeydbgAci4fgCaCRbbgCceaAcrGgAtV86bbaCcu7aA4ceGalfhlaeclfheaOcufgOmbkcualcdtalcFFFFi0Ehekaecbyd;y:L:cjbHjjjjbbhzasc:Cefasyd;8egecdtfazBdbasaecefBd;8ealcd4alfhOcehHinaHgecethHaeaO6mbkcbhXcuaecdtgOaecFFFFi0Ecbyd;y:L:cjbHjjjjbbhHasc:Cefasyd;8egAcdtfaHBdbasaAcefBd;8eaHcFeaOz:xjjjbhQdnadTmbaecufhLcbhKindndnaQabaKcdtfgYydbgAc:v;t;h;Ev2aLGgOcdtfgCydbgHcuSmbceheinazaHcdtfydbaASmdaOaefhHaecefheaQaHaLGgOcdtfgCydbgHcu9hmbkkazaXcdtfaABdbaCaXBdbaXhHaXcefhXkaYaHBdbaKcefgKad9hmbkkaQcbyd;C:L:cjbH:bjjjbbasasyd;8ecufBd;8ekcbh8AcualcefgecdtaecFFFFi0Ecbyd;y:L:cjbHjjjjbbhKasc:Cefasyd;8egecdtfaKBdbasaKBdNeasaecefBd;8ecuadcitadcFFFFe0Ecbyd;y:L:cjbHjjjjbbhEasc:Cefasyd;8egecdtfaEBdbasaEBd:yeasaecefBd;8eascNefabadalcbz:cjjjbcualcdtgealcFFFFi0Eg3cbyd;y:L:cjbHjjjjbbhHasc:Cefasyd;8egOcdtfaHBdbasaOcefBd;8ea3cbyd;y:L:cjbHjjjjbbhXasc:Cefasyd;8egOcdtfaXBdbasaOcefBd;8eaHaXaialavazasc:Cefz:djjjbalcbyd;y:L:cjbHjjjjbbh5asc:Cefasyd;8egOcdtfa5BdbasaOcefBd;8ea3cbyd;y:L:cjbHjjjjbbhOasc:Cefasyd;8egAcdtfaOBdbasaAcefBd;8ea3cbyd;y:L:cjbHjjjjbbhAasc:Cefasyd;8egCcdtfaABdbasaCcefBd;8eaOcFeaez:xjjjbh8EaAcFeaez:xjjjbh8FdnalTmbindnaKa8AgAcefg8AcdtfydbgCaKaAcdtgefydbgOSmbaCaO9RhYaEaOcitfhaa8Faefhha8EaefhLcbhCindndnaaaCcitfydbgQaA9hmbaLaABdbahaABdbxekdnaKaQcdtggfgeclfydbgOaeydbgeSmbaOae9RhOaEaecitfheinaeydbaASmdaecwfheaOcufgOmbkka8FagfgeaAaQaeydbcuSEBdbaLaQaAaLydbcuSEBdbkaCcefgCaY9hmbkka8Aal9hmbkaHhOaXhAa8EhQa8FhCcbheindndnaeaOydbgL9hmbdnaeaAydbgL9hmbaQydbhLdnaCydbgYcu9hmbaLcu9hmba5aefcb86bbxikdnaYcuSmbaLcuSmbaeaYSmbaHaYcdtfydbaHaLcdtfydb9hmba5aefcd86bbxika5aefhadnaeaYSmbaeaLSmbaace86bbxikaacv86bbxdkdnaeaXaLcdtgYfydb9hmbdnaCydbgacuSmbaeaaSmbaQydbggcuSmbaeagSmba8FaYfydbghcuSmbahaLSmba8EaYfydbgYcuSmbaYaLSmbaHaacdtfydbgLaHaYcdtfydb9hmbaLaHagcdtfydbgYSmbaYaHahcdtfydb9hmba5aefcd86bbxika5aefcv86bbxdka5aefcv86bbxeka5aefa5aLfRbb86bbkaOclfhOaAclfhAaQclfhQaCclfhCalaecefge9hmbkdnamcaGTmbcbh8Jindndna5a8Jfg8KRbbg8Lc9:fPlbeebekdndndnaHa8Jcdtfydbgea8J9hmbcbhYcbh8MaqTmednazTmbcbh8Ma8JheinaqazaecdtgefydbfRbbce4a8MVceGh8MaXaefydbgea8J9hmbxikkcbh8Ma8JheinaqaefRbbce4a8MVceGh8MaXaecdtfydbgea8J9hmbxdkka5aefRbbhexeka8JheindnaKaecdtg8AfgeclfydbgOaeydbgeSmbaOae9RhgaEaecitfhhaHa8AfhacbhLinahaLcitfydbgQhednindnaKaecdtgCfgeclfydbgOaeydbgeSmbaOae9RhOaEaecitfheaaydbhAdninaHaeydbcdtfydbaASmeaecwfheaOcufgOTmdxbkkcbhexdkaXaCfydbgeaQ9hmbkcehekaYaeVhYaLcefgLag9hmbkkaXa8Afydbgea8J9hmbka8LclciaYceGEa8MEheka8Kae86bbka8Jcefg8Jal9hmbkkdnaqTmbdndnazTmbazheaHhOalhAindnaqaeydbfRbbceGTmba5aOydbfcv86bbkaeclfheaOclfhOaAcufgAmbxdkkaqheaHhOalhAindnaeRbbceGTmba5aOydbfcv86bbkaecefheaOclfhOaAcufgAmbkkaHhealhAa5hOindna5aeydbfRbbcv9hmbaOcv86bbkaeclfheaOcefhOaAcufgAmbkkamceGTmba5healhOindndnaeRbbcufPlbeebekaecv86bbkaecefheaOcufgOmbkkcbh8Ncualcx2alc;v:Q;v:Qe0Ecbyd;y:L:cjbHjjjjbbh8Kasc:Cefasyd;8egecdtfa8KBdbasaecefBd;8eascbBd:qeas9cb83i1ea8Kaialavazasc1efz:ejjjbhydndnaDmbcbh8PcbhaxekcbhaawhecbhOindnaeIdbJbbbb9ETmbasaacdtfaOBdbaacefhakaeclfheaDaOcefgO9hmbkcuaaal2gecdtaecFFFFi0Ecbyd;y:L:cjbHjjjjbbh8Pasc:Cefasyd;8egecdtfa8PBdbasaecefBd;8ealTmbdnaambcbhaxekarcd4hgdnazTmbaacdthhcbhLa8PhYinaoazaLcdtfydbag2cdtfhQasheaYhOaahAinaOaQaeydbcdtgCfIdbawaCfIdbNUdbaeclfheaOclfhOaAcufgAmbkaYahfhYaLcefgLal9hmbxdkkaacdthhcbhLa8PhYinaoaLag2cdtfhQasheaYhOaahAinaOaQaeydbcdtgCfIdbawaCfIdbNUdbaeclfheaOclfhOaAcufgAmbkaYahfhYaLcefgLal9hmbkkcualc8S2gOalc;D;O;f8U0EgCcbyd;y:L:cjbHjjjjbbheasc:Cefasyd;8egAcdtfaeBdbasaAcefBd;8eaecbaOz:xjjjbhIcbh8RcbhgdnaaTmbcbh8NaCcbyd;y:L:cjbHjjjjbbhgasc:Cefasyd;8egecdtfagBdbasaecefBd;8eagcbaOz:xjjjb8Acuaaal2gecltgOaecFFFFb0Ecbyd;y:L:cjbHjjjjbbh8Rasc:Cefasyd;8egecdtfa8RBdbasaecefBd;8ea8RcbaOz:xjjjb8AamcjjjjdGTmbcualcltgealcFFFFb0Ecbyd;y:L:cjbHjjjjbbh8Nasc:Cefasyd;8egOcdtfa8NBdbasaOcefBd;8ea8Ncbaez:xjjjb8AkdnadTmbcbhQabhOina8KaOclfydbgLcx2fgeIdba8KaOydbgYcx2fgAIdbg8S:tgRa8KaOcwfydbghcx2fgCIdlaAIdlg8U:tg8VNaeIdla8U:tg8WaCIdba8S:tg8XN:tg8Ya8YNa8WaCIdwaAIdwg8Z:tg80NaeIdwa8Z:tg8Wa8VN:tg81a81Na8Wa8XNaRa80N:tg80a80NMMg8V:rhBa8Yh8Xa80h8Wa81hRdna8VJbbbb9EgATmba8YaB:vh8Xa80aB:vh8Wa81aB:vhRkaIaHaYcdtfydbgCc8S2fgeaRaB:rg8VaRNNg83aeIdbMUdbaea8Wa8Va8WNgUNg85aeIdlMUdlaea8Xa8Va8XNg86Ng87aeIdwMUdwaeaRaUNgUaeIdxMUdxaea86aRNg88aeIdzMUdzaea8Wa86Ng89aeIdCMUdCaeaRa8Va8Xa8ZNaRa8SNa8Ua8WNMM:mg8:Ng86NgRaeIdKMUdKaea8Wa86Ng8WaeId3MUd3aea8Xa86Ng8XaeIdaMUdaaea86a8:Ng86aeId8KMUd8Kaea8VaeIdyMUdyaIaHaLcdtfydbgLc8S2fgea83aeIdbMUdbaea85aeIdlMUdlaea87aeIdwMUdwaeaUaeIdxMUdxaea88aeIdzMUdzaea89aeIdCMUdCaeaRaeIdKMUdKaea8WaeId3MUd3aea8XaeIdaMUdaaea86aeId8KMUd8Kaea8VaeIdyMUdyaIaHahcdtfydbgYc8S2fgea83aeIdbMUdbaea85aeIdlMUdlaea87aeIdwMUdwaeaUaeIdxMUdxaea88aeIdzMUdzaea89aeIdCMUdCaeaRaeIdKMUdKaea8WaeId3MUd3aea8XaeIdaMUdaaea86aeId8KMUd8Kaea8VaeIdyMUdydna8NTmbdnaATmba8YaB:vh8Ya80aB:vh80a81aB:vh81ka8NaCcltfgeaBJbbbZNgRa80Ng8VaeIdlMUdlaeaRa8YNg8WaeIdwMUdwaeaRa81Ng8XaeIdbMUdbaeaRa8S:ma81Na8Ua80N:ta8Za8YN:tNgRaeIdxMUdxa8NaLcltfgea8VaeIdlMUdlaea8WaeIdwMUdwaea8XaeIdbMUdbaeaRaeIdxMUdxa8NaYcltfgea8VaeIdlMUdlaea8WaeIdwMUdwaea8XaeIdbMUdbaeaRaeIdxMUdxkaOcxfhOaQcifgQad6mbkkdnalTmbJq;x8J88J;n;m;m89J:v:;;w8ZamczGEamc;abGEh80cbhOaHhCazhQaIhea8KhAindnaOaCydb9hmbaOhLdnazTmbaQydbhLka80hRdnaqTmbJbbjZa80aqaLfRbbclGEhRkaecxfgLaLIdbJbbbbMUdbaeczfgLaLIdbJbbbbMUdbaecCfgLaLIdbJbbbbMUdbaeaRaecyfgLIdbg8YNgRaeIdbMUdbaeclfgYaRaYIdbMUdbaecwfgYaRaYIdbMUdbaecKfgYaYIdbaAIdbg8WaRN:tUdbaAcwfIdbh8Vaec3fgYaYIdbaRaAclfIdbg8XN:tUdbaecafgYaYIdbaRa8VN:tUdbaec8KfgYIdbh81aLa8YaRMUdbaYa81aRa8Va8VNa8Wa8WNa8Xa8XNMMNMUdbkaCclfhCaQclfhQaec8SfheaAcxfhAalaOcefgO9hmbkkdnadTmbcbh8AabhLinaba8AcdtfhYcbheindna5aLaefydbgCfRbbgOTmba5aYaec:G:G:cjbfydbcdtfydbgQfRbbcFeGgATmbdnaOclSghmbaOci6mbaAclSmbaAcd0mekdnaOcd0mba8EaCcdtfydbaQ9hmekdnaAcd0mba8FaQcdtfydbaC9hmekdndnahmbaAcl9hmekaOciSmeaAciSmekJbbbZJbbbZJbbacaAcdSEaOcdSEhUdna8KaYaec:K:G:cjbfydbcdtfydbcx2fgOIdwa8KaCcx2fgAIdwg86:tg8Sa8KaQcx2fghIdwa86:tg8Xa8XNahIdbaAIdbg8U:tg80a80NahIdlaAIdlg8Z:tg8Va8VNMMg81Na8Xa8Sa8XNaOIdba8U:tg83a80Na8VaOIdla8Z:tg85NMMg8WN:tg8Ya8YNa83a81Na80a8WN:tgRaRNa85a81Na8Va8WN:tg8Wa8WNMMgBJbbbb9ETmba8YaB:rgB:vh8Ya8WaB:vh8WaRaB:vhRkaUa81:rNgBa8Ya86NaRa8UNa8Za8WNMM:mg81Ng87a81Nh88a80a85Na8Va83N:tg81a81Na8Va8SNa8Xa85N:tg8Va8VNa8Xa83Na80a8SN:tg8Xa8XNMMg83:rh80a8Ya87Nh85a8Wa87Nh89aRa87Nh87a8WaBa8YNg8SNh8:a8SaRNhZaRaBa8WNgnNhca8Ya8SNh8Ya8WanNh8WaRaBaRNNh8Sdna83Jbbbb9ETmba81a80:vh81a8Xa80:vh8Xa8Va80:vh8VkaIaHaCcdtfydbc8S2fgOaOIdba8Sa8VaUa80:rNgRa8VNNMg80MUdbaOa8Wa8XaRa8XNg8SNMg83aOIdlMUdlaOa8Ya81aRa81Ng8WNMg8YaOIdwMUdwaOaca8Va8SNMg8SaOIdxMUdxaOaZa8Wa8VNMgUaOIdzMUdzaOa8:a8Xa8WNMg8WaOIdCMUdCaOa87a8VaRa81a86Na8Va8UNa8Za8XNMMg86:mNgRNMg8VaOIdKMUdKaOa89a8XaRNMg8XaOId3MUd3aOa85a81aRNMg81aOIdaMUdaaOa88a86aRN:tgRaOId8KMUd8KaOaBaOIdyMUdyaIaHaQcdtfydbc8S2fgOa80aOIdbMUdbaOa83aOIdlMUdlaOa8YaOIdwMUdwaOa8SaOIdxMUdxaOaUaOIdzMUdzaOa8WaOIdCMUdCaOa8VaOIdKMUdKaOa8XaOId3MUd3aOa81aOIdaMUdaaOaRaOId8KMUd8KaOaBaOIdyMUdykaeclfgecx9hmbkaLcxfhLa8Acifg8Aad6mbkkdnamcjeGTmbalTmbcbh9cindnaKa9cgecdtgOfydbghaKaecefg9ccdtfydbg8M9pmba8Kaecx2fhDaIaHaOfydbgCc8S2fh8AindnaHaEahcitfgeydbgLcdtfydbg8JaC0mbaeydlh8LcuhAaLheindnaKaecdtgYfgeclfydbgOaeydbgeSmbaOae9RhOaEaecitfheindnaHaeydbcdtfydbaC9hmbaAcu9hhQaLhAaQmbaeclfydbhAkaecwfheaOcufgOmbkkaXaYfydbgeaL9hmbkaAaLSmbaAcuSmba8KaLcx2fgeIdbaDIdbg81:tgRa8Ka8Lcx2fgOIdlaDIdlg80:tg8XNaeIdla80:tg8VaOIdba81:tg8YN:tg86a8KaAcx2fgAIdba81:tg8Za8VNaAIdla80:tg83aRN:tg8SNa8VaOIdwaDIdwgB:tg8UNaeIdwaB:tg8Wa8XN:tg85a83a8WNaAIdwaB:tg87a8VN:tgUNa8Wa8YNaRa8UN:tg88a87aRNa8Za8WN:tg89NMMa86a86Na85a85Na88a88NMM:rJ:A:z9z:;Na8Sa8SNaUaUNa89a89NMM:rN9Gmbdna8Ua8Wa8WNaRaRNa8Va8VNMMg8SNa8Wa8Ua8WNa8YaRNa8Va8XNMMg86N:tg8Ua8UNa8Ya8SNaRa86N:tg8Ya8YNa8Xa8SNa8Va86N:tg86a86NMMg8XJbbbb9ETmba8Ua8X:rg8X:vh8Ua86a8X:vh86a8Ya8X:vh8Yka8S:rg8Xa8UaBNa8Ya81Na80a86NMM:mgUNg85aUNhUa8Ua85Nh88a86a85Nh89a8Ya85Nh8:a86a8Xa8UNg85NhZa85a8YNhna8Ya8Xa86NgcNhJa8Ua85Nh8Ua86acNh86a8Ya8Xa8YNNh85dna87a8SNa8Wa87a8WNa8ZaRNa8Va83NMMg8YN:tg8Wa8WNa8Za8SNaRa8YN:tgRaRNa83a8SNa8Va8YN:tg8Va8VNMMg8YJbbbb9ETmba8Wa8Y:rg8Y:vh8Wa8Va8Y:vh8VaRa8Y:vhRka8Aa8AIdba85aRa8XaRNNMg8SMUdba8Aa86a8Va8Xa8VNg8ZNMg86a8AIdlMUdla8Aa8Ua8Wa8Xa8WNg8YNMg8Ua8AIdwMUdwa8AaJaRa8ZNMg8Za8AIdxMUdxa8Aana8YaRNMg83a8AIdzMUdza8AaZa8Va8YNMg85a8AIdCMUdCa8Aa8:aRa8Xa8WaBNaRa81Na80a8VNMMg81:mNg8YNMgRa8AIdKMUdKa8Aa89a8Va8YNMg8Va8AId3MUd3a8Aa88a8Wa8YNMg8Wa8AIdaMUdaa8AaUa81a8YN:tg8Ya8AId8KMUd8Ka8Aa8Xa8XMg8Xa8AIdyMUdyaIa8Jc8S2fgea8SaeIdbMUdbaea86aeIdlMUdlaea8UaeIdwMUdwaea8ZaeIdxMUdxaea83aeIdzMUdzaea85aeIdCMUdCaeaRaeIdKMUdKaea8VaeId3MUd3aea8WaeIdaMUdaaea8YaeId8KMUd8Kaea8XaeIdyMUdykahcefgha8M9hmbkka9cal9hmbkkdnadTmbaaTmbcbhYinJbbbbh80a8KabaYcdtfgeclfydbgLcx2fgOIdwa8Kaeydbghcx2fgAIdwg8Z:tg8Va8VNaOIdbaAIdbg83:tg8Wa8WNaOIdlaAIdlg85:tg8Xa8XNMMg8Sa8Kaecwfydbg8Acx2fgeIdwa8Z:tg8YNa8Va8YNa8WaeIdba83:tg81Na8XaeIdla85:tgBNMMgRa8VN:tJbbbbJbbjZa8Sa8Ya8YNa81a81NaBaBNMMg8UNaRaRN:tg86:va86Jbbbb9BEg86Nh88a8Ua8VNaRa8YN:ta86Nh89a8SaBNaRa8XN:ta86Nh8:a8Ua8XNaRaBN:ta86NhZa8Sa81NaRa8WN:ta86Nhna8Ua8WNaRa81N:ta86Nhca8WaBNa8Xa81N:tgRaRNa8Xa8YNa8VaBN:tgRaRNa8Va81Na8Wa8YN:tgRaRNMM:rJbbbZNhRa8Pahaa2g8JcdtfhOa8Pa8Aaa2g8McdtfhAa8PaLaa2gDcdtfhCa8Z:mhJa85:mh9ea83:mhTascjdfheaahQJbbbbhBJbbbbh86Jbbbbh8SJbbbbh8UJbbbbh8ZJbbbbh83Jbbbbh85Jbbbbh87JbbbbhUinaecwfaRa89aCIdbaOIdbg8Y:tg8XNa88aAIdba8Y:tg81NMg8VNUdbaeclfaRaZa8XNa8:a81NMg8WNUdbaeaRaca8XNana81NMg8XNUdbaecxfaRaJa8VNa9ea8WNa8YaTa8XNMMMg8YNUdbaRa8Va8WNNa8ZMh8ZaRa8Va8XNNa8UMh8UaRa8Wa8XNNa8SMh8SaRa8Ya8YNNaUMhUaRa8Va8YNNa87Mh87aRa8Wa8YNNa85Mh85aRa8Xa8YNNa83Mh83aRa8Va8VNNa86Mh86aRa8Wa8WNNaBMhBaRa8Xa8XNNa80Mh80aOclfhOaCclfhCaAclfhAaeczfheaQcufgQmbkagahc8S2fgea80aeIdbMUdbaeaBaeIdlMUdlaea86aeIdwMUdwaea8SaeIdxMUdxaea8UaeIdzMUdzaea8ZaeIdCMUdCaea83aeIdKMUdKaea85aeId3MUd3aea87aeIdaMUdaaeaUaeId8KMUd8KaeaRaeIdyMUdyagaLc8S2fgea80aeIdbMUdbaeaBaeIdlMUdlaea86aeIdwMUdwaea8SaeIdxMUdxaea8UaeIdzMUdzaea8ZaeIdCMUdCaea83aeIdKMUdKaea85aeId3MUd3aea87aeIdaMUdaaeaUaeId8KMUd8KaeaRaeIdyMUdyaga8Ac8S2fgea80aeIdbMUdbaeaBaeIdlMUdlaea86aeIdwMUdwaea8SaeIdxMUdxaea8UaeIdzMUdzaea8ZaeIdCMUdCaea83aeIdKMUdKaea85aeId3MUd3aea87aeIdaMUdaaeaUaeId8KMUd8KaeaRaeIdyMUdya8Ra8JcltfhLcbhOaahCinaLaOfgeascjdfaOfgAIdbaeIdbMUdbaeclfgQaAclfIdbaQIdbMUdbaecwfgQaAcwfIdbaQIdbMUdbaecxfgeaAcxfIdbaeIdbMUdbaOczfhOaCcufgCmbka8RaDcltfhLcbhOaahCinaLaOfgeascjdfaOfgAIdbaeIdbMUdbaeclfgQaAclfIdbaQIdbMUdbaecwfgQaAcwfIdbaQIdbMUdbaecxfgeaAcxfIdbaeIdbMUdbaOczfhOaCcufgCmbka8Ra8McltfhLcbhOaahCinaLaOfgeascjdfaOfgAIdbaeIdbMUdbaeclfgQaAclfIdbaQIdbMUdbaecwfgQaAcwfIdbaQIdbMUdbaecxfgeaAcxfIdbaeIdbMUdbaOczfhOaCcufgCmbkaYcifgYad6mbkkcbhAdndnamcwGgSmbJbbbbh86cbh9hcbh9icbh6xekcbh9ha3cbyd;y:L:cjbHjjjjbbh6asc:Cefasyd;8egecdtfa6BdbasaecefBd;8ecua6alabadaHz:fjjjbgCcltaCcjjjjiGEcbyd;y:L:cjbHjjjjbbh9iasc:Cefasyd;8egecdtfa9iBdbasaecefBd;8ea9iaCa6a8Kalz:gjjjbJFFuuh86aCTmba9iheaChOinaeIdbgRa86a86aR9EEh86aeclfheaOcufgOmbkaCh9hkdnalTmbaKclfheaKydbhCa5hOalhQcbhAincbaeydbgLaC9RaORbbcpeGEaAfhAaOcefhOaeclfheaLhCaQcufgQmbkaAce4hAkcuadaA9Rcifg9kcx2a9kc;v:Q;v:Qe0Ecbyd;y:L:cjbHjjjjbbh0asc:Cefasyd;8egecdtfa0BdbasaecefBd;8ecua9kcdta9kcFFFFi0Ecbyd;y:L:cjbHjjjjbbh9masc:Cefasyd;8egecdtfa9mBdbasaecefBd;8ea3cbyd;y:L:cjbHjjjjbbh9nasc:Cefasyd;8egecdtfa9nBdbasaecefBd;8ealcbyd;y:L:cjbHjjjjbbh9oasc:Cefasyd;8egecdtfa9oBdbasaecefBd;8eaxaxNayJbbjZamclGEg9pa9pN:vh87JbbbbhUdnadak9nmbdna9kci6mbamcjdGh9qaaclth9ra0cwfh9sJbbbbh85JbbbbhUinascNefabadalaHz:cjjjbabh8Acbh3cbh9tinaba9tcdtfh8McbheindnaHa8AaefydbgAcdtghfydbgCaHa8Maec:W:G:cjbfydbcdtfydbgOcdtg8JfydbgQSmba5aOfRbbgYco2a5aAfRbbgLfRb;a:G:cjbg8LaLco2aYfgDRb;a:G:cjbg9cVcFeGTmbdnaQaC9nmbaDRb;W:G:cjbcFeGmekdnaLcufcFeGce0mbaYTmba8EahfydbaO9hmekdnaLTmbaYcufcFeGce0mba8Fa8JfydbaA9hmeka0a3cx2fgCaOaAa9ccFeGgQEBdlaCaAaOaQEBdbaCaQa8LGcb9hBdwa3cefh3kaeclfgecx9hmbkdna9tcifg9tad9pmba8Acxfh8Aa3cifa9k9nmekka3TmdcbhDinaIaHa0aDcx2fghydbgLcdtgCfydbg8Jc8S2fgeIdwa8KahydlgYcx2fgOIdwg8WNaeIdzaOIdbg8XNaeIdaMgRaRMMa8WNaeIdlaOIdlg8YNaeIdCa8WNaeId3MgRaRMMa8YNaeIdba8XNaeIdxa8YNaeIdKMgRaRMMa8XNaeId8KMMM:lhRJbbbbJbbjZaeIdyg8V:va8VJbbbb9BEh8Vdndnahydwg8MmbJFFuuhBxekJbbbbJbbjZaIaHaYcdtfydbc8S2fgeIdyg81:va81Jbbbb9BEaeIdwa8KaLcx2fgOIdwg81NaeIdzaOIdbg80NaeIdaMgBaBMMa81NaeIdlaOIdlgBNaeIdCa81NaeId3Mg81a81MMaBNaeIdba80NaeIdxaBNaeIdKMg81a81MMa80NaeId8KMMM:lNhBka8VaRNh80dnaaTmbagaLc8S2fgAIdwa8WNaAIdza8XNaAIdaMgRaRMMa8WNaAIdla8YNaAIdCa8WNaAId3MgRaRMMa8YNaAIdba8XNaAIdxa8YNaAIdKMgRaRMMa8XNaAId8KMMMhRa8PaYaa2gQcdtfhOa8RaLaa2g8AcltfheaAIdyh81aahAinaOIdbg8Va8Va81NaecxfIdba8WaecwfIdbNa8XaeIdbNa8YaeclfIdbNMMMg8Va8VM:tNaRMhRaOclfhOaeczfheaAcufgAmbkaR:lgRa81aRa819DEaRa9qEh8Sdndna8MmbJbbbbhRxekagaYc8S2fgAIdwa8KaLcx2fgeIdwg8WNaAIdzaeIdbg8XNaAIdaMgRaRMMa8WNaAIdlaeIdlg8YNaAIdCa8WNaAId3MgRaRMMa8YNaAIdba8XNaAIdxa8YNaAIdKMgRaRMMa8XNaAId8KMMMhRa8Pa8AcdtfhOa8RaQcltfheaAIdyh81aahAinaOIdbg8Va8Va81NaecxfIdba8WaecwfIdbNa8XaeIdbNa8YaeclfIdbNMMMg8Va8VM:tNaRMhRaOclfhOaeczfheaAcufgAmbkaR:lgRa81aRa819DEaRa9qEhRka80a8SMh80aBaRMhBdndndna5aLfRbbc9:fPibeedkdna8Fa8Ea8EaCfydbaYSEaXaCfydbgQcdtfydbgCcu9hmbaXaYcdtfydbhCkagaQc8S2fgAIdwa8KaCcx2fgeIdwg8WNaAIdzaeIdbg8XNaAIdaMgRaRMMa8WNaAIdlaeIdlg8YNaAIdCa8WNaAId3MgRaRMMa8YNaAIdba8XNaAIdxa8YNaAIdKMgRaRMMa8XNaAId8KMMMhRa8PaCaa2g8AcdtfhOa8RaQaa2g8JcltfheaAIdyh81aahAinaOIdbg8Va8Va81NaecxfIdba8WaecwfIdbNa8XaeIdbNa8YaeclfIdbNMMMg8Va8VM:tNaRMhRaOclfhOaeczfheaAcufgAmbkaR:lgRa81aRa819DEaRa9qEh8Sdndna8MmbJbbbbhRxekagaCc8S2fgAIdwa8KaQcx2fgeIdwg8WNaAIdzaeIdbg8XNaAIdaMgRaRMMa8WNaAIdlaeIdlg8YNaAIdCa8WNaAId3MgRaRMMa8YNaAIdba8XNaAIdxa8YNaAIdKMgRaRMMa8XNaAId8KMMMhRa8Pa8JcdtfhOa8Ra8AcltfheaAIdyh81aahAinaOIdbg8Va8Va81NaecxfIdba8WaecwfIdbNa8XaeIdbNa8YaeclfIdbNMMMg8Va8VM:tNaRMhRaOclfhOaeczfheaAcufgAmbkaR:lgRa81aRa819DEaRa9qEhRka80a8SMh80aBaRMhBxdkaXaCfydbgCaLSmbaHaYcdtfydbh8Aindndna8EaCcdtgQfydbgecuSmbaHaecdtfydba8ASmekdna8FaQfydbgecuSmbaHaecdtfydba8ASmekaYhekagaCc8S2fgAIdwa8Kaecx2fgOIdwg8WNaAIdzaOIdbg8XNaAIdaMgRaRMMa8WNaAIdlaOIdlg8YNaAIdCa8WNaAId3MgRaRMMa8YNaAIdba8XNaAIdxa8YNaAIdKMgRaRMMa8XNaAId8KMMMhRa8Paeaa2cdtfhOa8RaCaa2cltfheaAIdyh81aahAinaOIdbg8Va8Va81NaecxfIdba8WaecwfIdbNa8XaeIdbNa8YaeclfIdbNMMMg8Va8VM:tNaRMhRaOclfhOaeczfheaAcufgAmbka80aR:lgRa81aRa819DEaRa9qEMh80aXaQfydbgCaL9hmbkkdna5aYfRbbgeciSmbaecl9hmeka8MTmbaXaYcdtfydbgCaYSmbindndna8EaCcdtgQfydbgecuSmbaHaecdtfydba8JSmekdna8FaQfydbgecuSmbaHaecdtfydba8JSmekaLhekagaCc8S2fgAIdwa8Kaecx2fgOIdwg8WNaAIdzaOIdbg8XNaAIdaMgRaRMMa8WNaAIdlaOIdlg8YNaAIdCa8WNaAId3MgRaRMMa8YNaAIdba8XNaAIdxa8YNaAIdKMgRaRMMa8XNaAId8KMMMhRa8Paeaa2cdtfhOa8RaCaa2cltfheaAIdyh81aahAinaOIdbg8Va8Va81NaecxfIdba8WaecwfIdbNa8XaeIdbNa8YaeclfIdbNMMMg8Va8VM:tNaRMhRaOclfhOaeczfheaAcufgAmbkaBaR:lgRa81aRa819DEaRa9qEMhBaXaQfydbgCaY9hmbkkahaBa80aBa809DgeEUdwahaLaYaea8Mcb9hGgeEBdlahaYaLaeEBdbaDcefgDa39hmbkascjdfcbcj;qbz:xjjjb8Aa9shea3hOinascjdfaeydbcA4cF8FGgAcFAaAcFA6EcdtfgAaAydbcefBdbaecxfheaOcufgOmbkcbhecbhOinascjdfaefgAydbhCaAaOBdbaCaOfhOaeclfgecj;qb9hmbkcbhea9shOinascjdfaOydbcA4cF8FGgAcFAaAcFA6EcdtfgAaAydbgAcefBdba9maAcdtfaeBdbaOcxfhOa3aecefge9hmbkadak9RgAci9Uh9udnalTmbcbhea9nhOinaOaeBdbaOclfhOalaecefge9hmbkkcbh9va9ocbalz:xjjjbh9caAcO9Uh9wa9uce4h9tcbh8Lcbh8Mdnina0a9ma8Mcdtfydbcx2fg8JIdwgRa879Emea8La9u9pmeJFFuuh8Vdna9ta39pmba0a9ma9tcdtfydbcx2fIdwJbb;aZNh8VkdnaRa8V9ETmbaRaU9ETmba8La9w0mdkdna9caHa8JydlgDcdtg9xfg8AydbgAfg9yRbba9caHa8Jydbghcdtg9zfydbgefg9ARbbVmba5ahfRbbh9BdndnaKaecdtfgOclfydbgCaOydbgOSmbaCaO9RhCa8KaAcx2fhLa8Kaecx2fhYaEaOcitfheindna9naeydbcdtfydbgOaASmba9naeclfydbcdtfydbgQaASmbaOaQSmba8KaQcx2fgQIdba8KaOcx2fgOIdbg8W:tgRaYIdlaOIdlg8X:tg80NaQIdla8X:tg8VaYIdba8W:tgBN:tg8YaRaLIdla8X:tg8SNa8VaLIdba8W:tg8UN:tg8XNa8VaYIdwaOIdwg81:tg8ZNaQIdwa81:tg8Wa80N:tg80a8VaLIdwa81:tg83Na8Wa8SN:tg8VNa8WaBNaRa8ZN:tg81a8Wa8UNaRa83N:tgRNMMa8Ya8YNa80a80Na81a81NMMa8Xa8XNa8Va8VNaRaRNMMN:rJbbj8:N9FmikaecwfheaCcufgCmbkkdndna9Bc99fcFeGce0mba9na9zfaDBdbaXa9zfydbgeahSmeina8AydbhAdndna8EaecdtgOfydbgecuSmbaHaecdtfydbaASmekdna8FaOfydbgecuSmbaHaecdtfydbaASmekaDheka9naOfaeBdbaXaOfydbgeah9hmbxdkkdndna9BcFeGcdSmbaDhexekdna8Fa8Ea8Ea9zfydbaDSEaXa9zfydbghcdtfydbgecu9hmbaXa9xfydbheka9na9zfaDBdbka9nahcdtfaeBdbka9Ace86bba9yce86bba8JIdwgRaUaUaR9DEhUa9vcefh9vcecda9BcFeGceSEa8Lfh8Lxeka9tcefh9tka8Mcefg8Ma39hmbkka9vTmddnalTmbcbhLcbhhindna9nahcdtgefydbgAahSmbaHaAcdtfydbh8AdnahaHaefydb9hg8JmbaIa8Ac8S2fgeaIahc8S2fgOIdbaeIdbMUdbaeaOIdlaeIdlMUdlaeaOIdwaeIdwMUdwaeaOIdxaeIdxMUdxaeaOIdzaeIdzMUdzaeaOIdCaeIdCMUdCaeaOIdKaeIdKMUdKaeaOId3aeId3MUd3aeaOIdaaeIdaMUdaaeaOId8KaeId8KMUd8KaeaOIdyaeIdyMUdya8NTmba8Na8Acltfgea8NahcltfgOIdbaeIdbMUdbaeaOIdlaeIdlMUdlaeaOIdwaeIdwMUdwaeaOIdxaeIdxMUdxkaaTmbagaAc8S2fgeagahc8S2g8MfgOIdbaeIdbMUdbaeaOIdlaeIdlMUdlaeaOIdwaeIdwMUdwaeaOIdxaeIdxMUdxaeaOIdzaeIdzMUdzaeaOIdCaeIdCMUdCaeaOIdKaeIdKMUdKaeaOId3aeId3MUd3aeaOIdaaeIdaMUdaaeaOId8KaeId8KMUd8KaeaOIdyaeIdyMUdya9raA2hYa8RhOaahCinaOaYfgeaOaLfgAIdbaeIdbMUdbaeclfgQaAclfIdbaQIdbMUdbaecwfgQaAcwfIdbaQIdbMUdbaecxfgeaAcxfIdbaeIdbMUdbaOczfhOaCcufgCmbka8JmbJbbbbJbbjZaIa8MfgeIdygR:vaRJbbbb9BEaeIdwa8Ka8Acx2fgOIdwgRNaeIdzaOIdbg8VNaeIdaMg8Wa8WMMaRNaeIdlaOIdlg8WNaeIdCaRNaeId3MgRaRMMa8WNaeIdba8VNaeIdxa8WNaeIdKMgRaRMMa8VNaeId8KMMM:lNgRa85a85aR9DEh85kaLa9rfhLahcefghal9hmbkcbhOa8EheindnaeydbgAcuSmbdnaOa9naAcdtgCfydbgA9hmbcuhAa8EaCfydbgCcuSmba9naCcdtfydbhAkaeaABdbkaeclfhealaOcefgO9hmbkcbhOa8FheindnaeydbgAcuSmbdnaOa9naAcdtgCfydbgA9hmbcuhAa8FaCfydbgCcuSmba9naCcdtfydbhAkaeaABdbkaeclfhealaOcefgO9hmbkka85aUaaEh85cbhOabhecbhAindnaHa9naeydbcdtfydbgLcdtfydbgCaHa9naeclfydbcdtfydbgYcdtfydbgQSmbaCaHa9naecwfydbcdtfydbg8AcdtfydbghSmbaQahSmbabaOcdtfgCaLBdbaCcwfa8ABdbaCclfaYBdbaOcifhOkaecxfheaAcifgAad6mbkdndnaSmbaOhdxekdnaOak0mbaOhdxekdna86a859FmbaOhdxekJFFuuh86cbhdabhecbhAindna9ia6aeydbgCcdtfydbcdtfIdbgRa859ETmbaeclf8Pdbh9CabadcdtfgQaCBdbaQclfa9C83dbaRa86a86aR9EEh86adcifhdkaecxfheaAcifgAaO6mbkkadak0mbxdkkascNefabadalaHz:cjjjbkdndnadak0mbadhYxekdnaSmbadhYxekdna86a879FmbadhYxekcehQina86Jbb;aZNgRa87aRa879DEh8WJbbbbhRdna9hTmba9ihea9hhOinaeIdbg8VaRa8Va8W9FEaRa8VaR9EEhRaeclfheaOcufgOmbkkJFFuuh86cbhYabhecbhOindna9ia6aeydbgAcdtfydbcdtfIdbg8Va8W9ETmbaeclf8Pdbh9CabaYcdtfgCaABdbaCclfa9C83dba8Va86a86a8V9EEh86aYcifhYkaecxfheaOcifgOad6mbkdnaQaYad9hVceGmbadhYxdkaRaUaUaR9DEhUaYak9nmecbhQaYhda86a879FmbkkdnamcjjjjdGTmba9ocbalz:xjjjbh8AdnaYTmbabheaYhOina8AaeydbgAfce86bba8AaHaAcdtfydbfce86bbaeclfheaOcufgOmbkkascNefabaYalaHz:cjjjbdndnalTmbcbhCindna8AaCfRbbTmbdna5aCfRbbPlbeebekdnaHaCcdtgLfydbgeaCSmba8KaCcx2fgOa8Kaecx2fgeydwBdwaOae8Pdb83dbxekaIaCc8S2fgQIdygnanJL:3;rUNgRMh87aQIdwgxaRMh8SaQIdlg9DaRMh8UaQIdbg9EaRMh81aQIdag9FaRa8KaCcx2fg8JIdwg88N:th8ZaQId3g9GaRa8JIdlg89N:th83aQIdKg9Ha8JIdbg8:aRN:th80JbbbbhZaQIdCg9IJbbbbMh85aQIdzg9JJbbbbMhBaQIdxg9KJbbbbMh86dndnaaTmbaChAinJbbbba87agaAc8S2fgOIdygR:vaRJbbbb9BEhRa8RaAaa2cltfheaOIdaa87Na8ZMh8ZaOId3a87Na83Mh83aOIdKa87Na80Mh80aOIdCa87Na85Mh85aOIdza87NaBMhBaOIdxa87Na86Mh86aOIdwa87Na8SMh8SaOIdla87Na8UMh8UaOIdba87Na81Mh81aahOina8ZaecwfIdbg8VaecxfIdbg8YNaRN:th8Za83aeclfIdbg8Wa8YNaRN:th83a85a8Wa8VNaRN:th85a81aeIdbg8Xa8XNaRN:th81a80a8Xa8YNaRN:th80aBa8Xa8VNaRN:thBa86a8Xa8WNaRN:th86a8Sa8Va8VNaRN:th8Sa8Ua8Wa8WNaRN:th8UaeczfheaOcufgOmbkaXaAcdtfydbgAaC9hmbka8NTmba8NaCcltfgeIdxhTaeIdwhcaeIdlhJaeIdbhRxekJbbbbhTJbbbbhcJbbbbhJJbbbbhRkaBa81:vg8Wa80Na8Z:ta85aBa86a81:vg8VN:tg8Za8Ua86a8VN:tg8Y:vg8Xa8Va80Na83:tg8UN:th83acaRa8WN:taJaRa8VN:tg86a8XN:tg85a8SaBa8WN:ta8Za8XN:tgB:vg8S:mh8Za86a8Y:vgc:mhJdnJbbbbaRaRa81:vg9eN:ta86acN:ta85a8SN:tg86:la87J:983:g81NgR9ETmba8Za83NaJa8UNa9ea80NaT:tMMa86:vhZka81:laR9ETmba8Y:laR9ETmbaB:laR9ETmba9e:maZNa8W:ma8ZaZNa83aB:vMgBNa8V:maJaZNa8X:maBNa8Ua8Y:vMMg85Na80:ma81:vMMMh87aKaLfgeclfydbgOaeydbge9RhhaEaecitfhLJbbbbhRdnaOaeSg8MmbJbbbbhRaLheahhAina8Kaeclfydbcx2fgOIdwa88:tg8Va8VNaOIdba8::tg8Va8VNaOIdla89:tg8Va8VNMMg8Va8Kaeydbcx2fgOIdwa88:tg8Wa8WNaOIdba8::tg8Wa8WNaOIdla89:tg8Wa8WNMMg8WaRaRa8W9DEgRaRa8V9DEhRaecwfheaAcufgAmbkaR:rgRaRNhRkaBa88:tg8Va8VNa87a8::tg8Va8VNa85a89:tg8Va8VNMMaR9EmbaQId8KhZdna8Mmbina8KaLclfydbcx2fgeIdba8KaLydbcx2fgOIdbg8W:tgRa89aOIdlg8X:tg80NaeIdla8X:tg8Va8:a8W:tg86N:tg8YaRa85a8X:tg8SNa8Va87a8W:tg8UN:tg8XNa8Va88aOIdwg81:tg8ZNaeIdwa81:tg8Wa80N:tg80a8VaBa81:tg83Na8Wa8SN:tg8VNa8Wa86NaRa8ZN:tg81a8Wa8UNaRa83N:tgRNMMa8Ya8YNa80a80Na81a81NMMa8Xa8XNa8Va8VNaRaRNMMN:rJbbj8:N9FmdaLcwfhLahcufghmbkkJbbbbJbbjZan:vanJbbbb9BEgRaxaBNa9Ja87Na9FMg8Va8VMMaBNa9Da85Na9IaBNa9GMg8Va8VMMa85Na9Ea87Na9Ka85Na9HMg8Va8VMMa87NaZMMM:lNaRaxa88Na9Ja8:Na9FMg8Va8VMMa88Na9Da89Na9Ia88Na9GMg8Va8VMMa89Na9Ea8:Na9Ka89Na9HMg8Va8VMMa8:NaZMMM:lNJbb;aZNJ:983:g81M9Emba8JaBUdwa8Ja85Udla8Ja87UdbkaCcefgCal9hmbkdnaambcbhaxdkcbhQindna8AaQfRbbTmbaHaQcdtgefydbaQ9hmba5aQfhhaXaefh8Ja8KaQcx2fhAa8PaQaa2cdtfh8McbhEincuhCdnahRbbc99fcFeGce0mbaQhCa8JydbgeaQSmba8PaEcdtgOfhLa8MaOfIdbhRaQhCinaChOcuhCdnaLaeaa2cdtfIdbaR9CmbaOcuSmbaOhCagaec8S2fIdyagaOc8S2fIdy9ETmbaehCkaXaecdtfydbgeaQ9hmbkka8PaEcdtfhLa8RaEcltfhKaQheinaLaeaa2cdtfJbbbbJbbjZagaeaCaCcuSEgOc8S2fIdygR:vaRJbbbb9BEaKaOaa2cltfgOIdwaAIdwNaOIdbaAIdbNaOIdlaAIdlNMMaOIdxMNUdbaXaecdtfydbgeaQ9hmbkaEcefgEaa9hmbkkaQcefgQal9hmbxdkkaambcbhakaiavaoarawaaala8Ka8Pazasayasc1efa5a8Aaqz:hjjjbkdnamcjjjjlGTmbazmbaYTmbabhecbhLina5aeydbgAfRbbc3thQaecwfgXydbhHcjjjj94hCdna8EaAcdtgEfydbaeclfgKydbgOSmbcjjjj94cba8FaOcdtfydbaASEhCkaeaQaCVaAVBdba5aOfRbbc3thacjjjj94hCcjjjj94hQdna8EaOcdtfydbaHSmbcjjjj94cba8FaHcdtfydbaOSEhQkaKaaaQVaOVBdba5aHfRbbc3thOdna8EaHcdtfydbaASmbcjjjj94cba8FaEfydbaHSEhCkaXaOaCVaHVBdbaecxfheaLcifgLaY6mbkkdnazTmbaYTmbaYheinabazabydbcdtfydbBdbabclfhbaecufgembkkdnaPTmbaPa9paU:rNUdbkdnasyd;8egHTmbaHcdtasc:Ceffc98fheinaeydbcbyd;C:L:cjbH:bjjjbbaec98fheaHcufgHmbkkascj;sbf8KjjjjbaYk;Yieouabydlhvabydbclfcbaicdtz:xjjjbhoadci9UhrdnadTmbdnalTmbaehwadhDinaoalawydbcdtfydbcdtfgqaqydbcefBdbawclfhwaDcufgDmbxdkkaehwadhDinaoawydbcdtfgqaqydbcefBdbawclfhwaDcufgDmbkkdnaiTmbcbhDaohwinawydbhqawaDBdbawclfhwaqaDfhDaicufgimbkkdnadci6mbinaecwfydbhwaeclfydbhDaeydbhidnalTmbalawcdtfydbhwalaDcdtfydbhDalaicdtfydbhikavaoaicdtfgqydbcitfaDBdbavaqydbcitfawBdlaqaqydbcefBdbavaoaDcdtfgqydbcitfawBdbavaqydbcitfaiBdlaqaqydbcefBdbavaoawcdtfgwydbcitfaiBdbavawydbcitfaDBdlawawydbcefBdbaecxfhearcufgrmbkkabydbcbBdbk:todDue99aicd4aifhrcehwinawgDcethwaDar6mbkcuaDcdtgraDcFFFFi0Ecbyd;y:L:cjbHjjjjbbhwaoaoyd9GgqcefBd9GaoaqcdtfawBdbawcFearz:xjjjbhkdnaiTmbalcd4hlaDcufhxcbhminamhDdnavTmbavamcdtfydbhDkcbadaDal2cdtfgDydlgwawcjjjj94SEgwcH4aw7c:F:b:DD2cbaDydbgwawcjjjj94SEgwcH4aw7c;D;O:B8J27cbaDydwgDaDcjjjj94SEgDcH4aD7c:3F;N8N27axGhwamcdthPdndndnavTmbakawcdtfgrydbgDcuSmeadavaPfydbal2cdtfgsIdbhzcehqinaqhrdnadavaDcdtfydbal2cdtfgqIdbaz9CmbaqIdlasIdl9CmbaqIdwasIdw9BmlkarcefhqakawarfaxGgwcdtfgrydbgDcu9hmbxdkkakawcdtfgrydbgDcuSmbadamal2cdtfgsIdbhzcehqinaqhrdnadaDal2cdtfgqIdbaz9CmbaqIdlasIdl9CmbaqIdwasIdw9BmikarcefhqakawarfaxGgwcdtfgrydbgDcu9hmbkkaramBdbamhDkabaPfaDBdbamcefgmai9hmbkkakcbyd;C:L:cjbH:bjjjbbaoaoyd9GcufBd9GdnaeTmbaiTmbcbhDaehwinawaDBdbawclfhwaiaDcefgD9hmbkcbhDaehwindnaDabydbgrSmbawaearcdtfgrydbBdbaraDBdbkabclfhbawclfhwaiaDcefgD9hmbkkk;:odvuv998Jjjjjbca9Rgocbyd1:G:cjbBdKaocb8Pdj:G:cjb83izaocbydN:G:cjbBdwaocb8Pd:m:G:cjb83ibdnadTmbaicd4hrdnabmbdnalTmbcbhwinaealawcdtfydbar2cdtfhDcbhiinaoczfaifgqaDaifIdbgkaqIdbgxaxak9EEUdbaoaifgqakaqIdbgxaxak9DEUdbaiclfgicx9hmbkawcefgwad9hmbxikkarcdthwcbhDincbhiinaoczfaifgqaeaifIdbgkaqIdbgxaxak9EEUdbaoaifgqakaqIdbgxaxak9DEUdbaiclfgicx9hmbkaeawfheaDcefgDad9hmbxdkkdnalTmbcbhwinabawcx2fgiaealawcdtfydbar2cdtfgDIdbUdbaiaDIdlUdlaiaDIdwUdwcbhiinaoczfaifgqaDaifIdbgkaqIdbgxaxak9EEUdbaoaifgqakaqIdbgxaxak9DEUdbaiclfgicx9hmbkawcefgwad9hmbxdkkarcdthlcbhwaehDinabawcx2fgiaeawar2cdtfgqIdbUdbaiaqIdlUdlaiaqIdwUdwcbhiinaoczfaifgqaDaifIdbgkaqIdbgxaxak9EEUdbaoaifgqakaqIdbgxaxak9DEUdbaiclfgicx9hmbkaDalfhDawcefgwad9hmbkkJbbbbaoIdbaoIdzgx:tgkakJbbbb9DEgkaoIdlaoIdCgm:tgPaPak9DEgkaoIdwaoIdKgP:tgsasak9DEhsdnabTmbadTmbJbbbbJbbjZas:vasJbbbb9BEhkinabakabIdbax:tNUdbabclfgoakaoIdbam:tNUdbabcwfgoakaoIdbaP:tNUdbabcxfhbadcufgdmbkkdnavTmbavaPUdwavamUdlavaxUdbkask:WlewudnaeTmbcbhvabhoinaoavBdbaoclfhoaeavcefgv9hmbkkdnaiTmbcbhrinadarcdtfhwcbhDinalawaDcdtgvyd:G:G:cjbcdtfydbcdtfydbhodnalawavfydbcdtfydbgqabaqcdtfgkydbgvSmbinakabavgqcdtfgxydbgvBdbaxhkaqav9hmbkkdnaoabaocdtfgkydbgvSmbinakabavgocdtfgxydbgvBdbaxhkaoav9hmbkkdnaqaoSmbabaqaoaqao0Ecdtfaqaoaqao6EBdbkaDcefgDci9hmbkarcifgrai6mbkkdnaembcbskcbhxindnalaxcdtgvfydbax9hmbaxhodnaxabavfgDydbgvSmbaDhqinaqabavgocdtfgkydbgvBdbakhqaoav9hmbkkaDaoBdbkaxcefgxae9hmbkcbhkabhvcbhoindndnaoalydbgq9hmbdnaoavydbgq9hmbavakBdbakcefhkxdkavabaqcdtfydbBdbxekavabaqcdtfydbBdbkalclfhlavclfhvaeaocefgo9hmbkakk;jiilud99euabcbaecltz:xjjjbhvdnalTmbadhoaihralhwinarcwfIdbhDarclfIdbhqavaoydbcltfgkarIdbakIdbMUdbakaqakIdlMUdlakaDakIdwMUdwakakIdxJbbjZMUdxaoclfhoarcxfhrawcufgwmbkkdnaeTmbavhkaehrinakcxfgoIdbhDaocbBdbakakIdbJbbbbJbbjZaD:vaDJbbbb9BEgDNUdbakclfgoaDaoIdbNUdbakcwfgoaDaoIdbNUdbakczfhkarcufgrmbkkdnalTmbinavadydbcltfgkaicwfIdbakIdw:tgDaDNaiIdbakIdb:tgDaDNaiclfIdbakIdl:tgDaDNMMgDakIdxgqaqaD9DEUdxadclfhdaicxfhialcufglmbkkdnaeTmbavcxfhkinabakIdbUdbakczfhkabclfhbaecufgembkkk:moerudnaoTmbaecd4hzdnavTmbaicd4hHavcdthOcbhAindnaPaAfRbbTmbaAhednaDTmbaDaAcdtfydbhekdnasTmbasaefRbbceGmekdnamaAfRbbcvSmbabaeaz2cdtfgiaraAcx2fgCIdbakNaxIdbMUdbaiaCIdlakNaxIdlMUdlaiaCIdwakNaxIdwMUdwkadaeaH2cdtfhXaqheawhiavhCinaXaeydbcdtgQfaiIdbalaQfIdb:vUdbaeclfheaiclfhiaCcufgCmbkkawaOfhwaAcefgAao9hmbxdkkdnasmbcbheaDhiindnaPaefRbbTmbaehCdnaDTmbaiydbhCkamaefRbbcvSmbabaCaz2cdtfgCarIdbakNaxIdbMUdbaCarclfIdbakNaxIdlMUdlaCarcwfIdbakNaxIdwMUdwkaiclfhiarcxfhraoaecefge9hmbxdkkdnaDTmbindnaPRbbTmbasaDydbgefRbbceGmbamRbbcvSmbabaeaz2cdtfgearIdbakNaxIdbMUdbaearclfIdbakNaxIdlMUdlaearcwfIdbakNaxIdwMUdwkaPcefhPaDclfhDamcefhmarcxfhraocufgombxdkkazcdthicbheindnaPaefRbbTmbasaefRbbceGmbamaefRbbcvSmbabarIdbakNaxIdbMUdbabclfarclfIdbakNaxIdlMUdbabcwfarcwfIdbakNaxIdwMUdbkarcxfhrabaifhbaoaecefge9hmbkkk8MbabaeadaialavcbcbcbcbcbaoarawaDz:bjjjbk8MbabaeadaialavaoarawaDaqakaxamaPz:bjjjbkRbababaeadaialavaoarawaDaqakaxcjjjjdVamz:bjjjbk:vgoque99due99duq998Jjjjjbc;Wb9Rgq8Kjjjjbcbhkaqcxfcbc;Kbz:xjjjb8Aaqcualcx2alc;v:Q;v:Qe0Ecbyd;y:L:cjbHjjjjbbgxBdxaqceBd2axaialavcbcbz:ejjjb8AaqcualcdtalcFFFFi0Egmcbyd;y:L:cjbHjjjjbbgiBdzaqcdBd2dndnJFF959eJbbjZawJbbjZawJbbjZ9DE:vawJ9VO:d869DEgw:lJbbb9p9DTmbaw:OhPxekcjjjj94hPkadci9Uhsarco9UhzdndnaombaPcd9imekdnalTmbaPcuf:YhwdnaoTmbcbhvaihHaxhOindndnaoavfRbbceGTmbavcjjjjlVhAxekdndnaOclfIdbawNJbbbZMgC:lJbbb9p9DTmbaC:OhAxekcjjjj94hAkaAcqthAdndnaOcwfIdbawNJbbbZMgC:lJbbb9p9DTmbaC:OhXxekcjjjj94hXkaAaXVhAdndnaOIdbawNJbbbZMgC:lJbbb9p9DTmbaC:OhXxekcjjjj94hXkaAaXcCtVhAkaHaABdbaHclfhHaOcxfhOalavcefgv9hmbxdkkaxhvaihOalhHindndnavIdbawNJbbbZMgC:lJbbb9p9DTmbaC:OhAxekcjjjj94hAkaAcCthAdndnavclfIdbawNJbbbZMgC:lJbbb9p9DTmbaC:OhXxekcjjjj94hXkaXcqtaAVhAdndnavcwfIdbawNJbbbZMgC:lJbbb9p9DTmbaC:OhXxekcjjjj94hXkaOaAaXVBdbavcxfhvaOclfhOaHcufgHmbkkadTmbcbhkaehvcbhOinakaiavclfydbcdtfydbgHaiavcwfydbcdtfydbgA9haiavydbcdtfydbgXaH9haXaA9hGGfhkavcxfhvaOcifgOad6mbkkarci9UhQdndnaz:Z:rJbbbZMgw:lJbbb9p9DTmbaw:Ohvxekcjjjj94hvkaQ:ZhLcbhKc:bwhzdninakaQ9pmeazaP9Rcd9imeavazcufgOavaO9iEaPcefavaP9kEhYdnalTmbaYcuf:YhwdnaoTmbcbhOaihHaxhvindndnaoaOfRbbceGTmbaOcjjjjlVhAxekdndnavclfIdbawNJbbbZMgC:lJbbb9p9DTmbaC:OhAxekcjjjj94hAkaAcqthAdndnavcwfIdbawNJbbbZMgC:lJbbb9p9DTmbaC:OhXxekcjjjj94hXkaAaXVhAdndnavIdbawNJbbbZMgC:lJbbb9p9DTmbaC:OhXxekcjjjj94hXkaAaXcCtVhAkaHaABdbaHclfhHavcxfhvalaOcefgO9hmbxdkkaxhvaihOalhHindndnavIdbawNJbbbZMgC:lJbbb9p9DTmbaC:OhAxekcjjjj94hAkaAcCthAdndnavclfIdbawNJbbbZMgC:lJbbb9p9DTmbaC:OhXxekcjjjj94hXkaXcqtaAVhAdndnavcwfIdbawNJbbbZMgC:lJbbb9p9DTmbaC:OhXxekcjjjj94hXkaOaAaXVBdbavcxfhvaOclfhOaHcufgHmbkkcbhOdnadTmbaehvcbhHinaOaiavclfydbcdtfydbgAaiavcwfydbcdtfydbgX9haiavydbcdtfydbgraA9haraX9hGGfhOavcxfhvaHcifgHad6mbkkdnas:ZgCaL:taY:Ygwaz:Y:tg8ANak:ZgEaO:Zg3:tNaEaL:tawaP:Y:tg5Na3aC:tNMg8EJbbbb9BmbaCaE:ta5a8Aa3aL:tNNNa8E:vawMhwkdndnaOaQ0mbaOhkaYhPxekaOhsaYhzkdndnaKcl0mbdnawJbbbZMgw:lJbbb9p9DTmbaw:Ohvxdkcjjjj94hvxekaPazfcd9ThvkaKcefgKcs9hmbkkdndndnakmbJbbjZhwcbhOcdhvaDmexdkalcd4alfhHcehOinaOgvcethOavaH6mbkaqcuavcdtavcFFFFi0Ecbyd;y:L:cjbHjjjjbbgYBdCaqciBd2aqamcbyd;y:L:cjbHjjjjbbgzBdKaqclBd2dnalTmbaPcuf:YhwdnaoTmbcbhOaihAaxhHindndnaoaOfRbbceGTmbaOcjjjjlVhXxekdndnaHclfIdbawNJbbbZMgC:lJbbb9p9DTmbaC:OhXxekcjjjj94hXkaXcqthXdndnaHcwfIdbawNJbbbZMgC:lJbbb9p9DTmbaC:Ohrxekcjjjj94hrkaXarVhXdndnaHIdbawNJbbbZMgC:lJbbb9p9DTmbaC:Ohrxekcjjjj94hrkaXarcCtVhXkaAaXBdbaAclfhAaHcxfhHalaOcefgO9hmbxdkkaxhOaihHalhAindndnaOIdbawNJbbbZMgC:lJbbb9p9DTmbaC:OhXxekcjjjj94hXkaXcCthXdndnaOclfIdbawNJbbbZMgC:lJbbb9p9DTmbaC:Ohrxekcjjjj94hrkarcqtaXVhXdndnaOcwfIdbawNJbbbZMgC:lJbbb9p9DTmbaC:Ohrxekcjjjj94hrkaHaXarVBdbaOcxfhOaHclfhHaAcufgAmbkkaqcuaYavazaialz:mjjjbgXc8S2gvaXc;D;O;f8U0Ecbyd;y:L:cjbHjjjjbbgiBd3aqcvBd2aicbavz:xjjjbhOdnadTmbcbhraehiinaxaiclfydbgocx2fgvIdbaxaiydbgPcx2fgHIdbg3:tgCaxaicwfydbgYcx2fgAIdlaHIdlg8A:tgwNavIdla8A:tgEaAIdba3:tg8EN:tgLaLNaEaAIdwaHIdwg5:tg8FNavIdwa5:tgEawN:tgwawNaEa8ENaCa8FN:tgCaCNMMg8E:rhEJbbnnJbbjZazaPcdtfydbgvazaocdtfydbgASavazaYcdtfydbgoSGgHEh8Fdna8EJbbbb9ETmbaLaE:vhLaCaE:vhCawaE:vhwkaOavc8S2fgvavIdbawa8FaE:rNgEawNNg8FMUdbavaCaEaCNgaNghavIdlMUdlavaLaEaLNg8ENggavIdwMUdwavawaaNgaavIdxMUdxava8EawNg8JavIdzMUdzavaCa8ENg8EavIdCMUdCavawaEaLa5Nawa3Na8AaCNMM:mg8ANg3NgwavIdKMUdKavaCa3NgCavId3MUd3avaLa3NgLavIdaMUdaava3a8ANg3avId8KMUd8KavaEavIdyMUdydnaHmbaOaAc8S2fgva8FavIdbMUdbavahavIdlMUdlavagavIdwMUdwavaaavIdxMUdxava8JavIdzMUdzava8EavIdCMUdCavawavIdKMUdKavaCavId3MUd3avaLavIdaMUdaava3avId8KMUd8KavaEavIdyMUdyaOaoc8S2fgva8FavIdbMUdbavahavIdlMUdlavagavIdwMUdwavaaavIdxMUdxava8JavIdzMUdzava8EavIdCMUdCavawavIdKMUdKavaCavId3MUd3avaLavIdaMUdaava3avId8KMUd8KavaEavIdyMUdykaicxfhiarcifgrad6mbkkcbhAaqcuaXcdtgvaXcFFFFi0Egicbyd;y:L:cjbHjjjjbbgHBdaaqcoBd2aqaicbyd;y:L:cjbHjjjjbbgiBd8KaqcrBd2aHcFeavz:xjjjbhPdnalTmbazhHinJbbbbJbbjZaOaHydbgrc8S2fgvIdygw:vawJbbbb9BEavIdwaxcwfIdbgwNavIdzaxIdbgCNavIdaMgLaLMMawNavIdlaxclfIdbgLNavIdCawNavId3MgwawMMaLNavIdbaCNavIdxaLNavIdKMgwawMMaCNavId8KMMM:lNhwdndnaParcdtgvfgrydbcuSmbaiavfIdbaw9ETmekaraABdbaiavfawUdbkaHclfhHaxcxfhxalaAcefgA9hmbkkdndnaXmbJbbbbhwxekJbbbbhwinaiIdbgCawawaC9DEhwaiclfhiaXcufgXmbkaw:rhwkakcd4akfhOcehiinaigvcethiavaO6mbkcbhOaqcuavcdtgiavcFFFFi0Ecbyd;y:L:cjbHjjjjbbgHBdyaHcFeaiz:xjjjbhXdnadTmbavcufhrcbhkcbhxindnazaeaxcdtfgvydbcdtfydbgiazavclfydbcdtfydbgOSmbaiazavcwfydbcdtfydbgvSmbaOavSmbaPavcdtfydbhAdndnaPaOcdtfydbgvaPaicdtfydbgi9pmbavaA9pmbaAhlaihoavhAxekdnaAai9pmbaAav9pmbaihlavhoxekavhlaAhoaihAkabakcx2fgvaABdbavcwfaoBdbavclfalBdbdnaXaoc:3F;N8N2alc:F:b:DD27aAc;D;O:B8J27arGgOcdtfgvydbgicuSmbcehHinaHhvdnabaicx2fgiydbaA9hmbaiydlal9hmbaiydwaoSmikavcefhHaXaOavfarGgOcdtfgvydbgicu9hmbkkavakBdbakcefhkkaxcifgxad6mbkakci2hOkcwhvaDTmekaDawUdbkavcdthvaqcxfc98fhiinaiavfydbcbyd;C:L:cjbH:bjjjbbavc98fgvmbkaqc;Wbf8KjjjjbaOk:0iewuabcFeaecdtz:xjjjbhbdnalmbcbskaecufhvdndnaiTmbcbhocbhrindndndnabaiarcdtgwfydbgDcm4aD7c:v;t;h;Ev2gecs4ae7avGgqcdtfgkydbgxcuSmbceheinaiaxcdtgxfydbaDSmdaqaefhxaecefheabaxavGgqcdtfgkydbgxcu9hmbkkakarBdbaoheaocefhoxekadaxfydbhekadawfaeBdbarcefgral9hmbxdkkcbhocbhDindnabaDcm4aD7c:v;t;h;Ev2gecs4ae7avGgqcdtfgkydbgxcuSmbaxaDSmbceheinabaqaefavGgqcdtfgkydbgxcuSmeaecefheaxaD9hmbkkdndnaxcu9hmbakaDBdbaoheaocefhoxekadaxcdtfydbhekadaDcdtfaeBdbaDcefgDal9hmbkkaok:3ldrue9:8Jjjjjbc;Wb9Rgr8Kjjjjbcbhwarcxfcbc;Kbz:xjjjb8AdnabaeSmbabaeadcdtz:wjjjb8AkarcualcdtalcFFFFi0EgDcbyd;y:L:cjbHjjjjbbgqBdxarceBd2aqcbaialavcbarcxfz:djjjbcualcx2alc;v:Q;v:Qe0Ecbyd;y:L:cjbHjjjjbbhkarcxfaryd2gxcdtfakBdbaraxcefgmBd2akaialavcbcbz:ejjjb8AarcxfamcdtfaDcbyd;y:L:cjbHjjjjbbgiBdbaraxcdfgvBd2arcxfavcdtfcuaialaeadaqz:fjjjbgecltaecjjjjiGEcbyd;y:L:cjbHjjjjbbgqBdbaqaeaiakalz:gjjjbaxcifhkdnadTmbaoaoNhocbhwabhlcbheindnaqaialydbgvcdtfydbcdtfIdbao9ETmbalclf8PdbhPabawcdtfgDavBdbaDclfaP83dbawcifhwkalcxfhlaecifgead6mbkkdnakTmbaxcdtarcxffcwfhlinalydbcbyd;C:L:cjbH:bjjjbbalc98fhlakcufgkmbkkarc;Wbf8Kjjjjbawk;lOoDud99oue99vuv998Jjjjjbc;Wb9Rgw8KjjjjbdndnarmbcbhDxekawcxfcbc;Kbz:xjjjb8Aawcuadcx2adc;v:Q;v:Qe0Ecbyd;y:L:cjbHjjjjbbgqBdxawceBd2aqaeadaicbcbz:ejjjb8AawcuadcdtadcFFFFi0Egkcbyd;y:L:cjbHjjjjbbgxBdzawcdBd2adcd4adfhecehiinaigmcethiamae6mbkcbhPawcuamcdtgsamcFFFFi0Ecbyd;y:L:cjbHjjjjbbgzBdCawciBd2dndnar:ZgH:rJbbbZMgO:lJbbb9p9DTmbaO:Ohixekcjjjj94hikamcufhAc:bwhCcbhXadhQcbhLinaiaCcufgeaiae9iEaPcefaiaP9kEhDdndnadTmbaDcuf:YhOaqhiaxheadhKindndnaiIdbaONJbbbZMgY:lJbbb9p9DTmbaY:Oh8Axekcjjjj94h8Aka8AcCth8AdndnaiclfIdbaONJbbbZMgY:lJbbb9p9DTmbaY:OhExekcjjjj94hEkaEcqta8AVh8AdndnaicwfIdbaONJbbbZMgY:lJbbb9p9DTmbaY:OhExekcjjjj94hEkaea8AaEVBdbaicxfhiaeclfheaKcufgKmbkazcFeasz:xjjjbh3cbh5cbh8Eindna3axa8Ecdtfydbg8Acm4a8A7c:v;t;h;Ev2gics4ai7aAGgKcdtfgEydbgecuSmbaea8ASmbcehiina3aKaifaAGgKcdtfgEydbgecuSmeaicefhiaea8A9hmbkkaEa8ABdba5aecuSfh5a8Ecefg8Ead9hmbxdkkazcFeasz:xjjjb8Acbh5kdnaQ:ZgYaH:taD:YgOaC:Y:tg8FNaX:Zgaa5:Zgh:tNaaaH:taOaP:Y:tggNahaY:tNMg8JJbbbb9BmbaYaa:taga8FahaH:tNNNa8J:vaOMhOkaPaDa5ar0geEhPaXa5aeEhXdna5arSmbaDaCaeEgCaP9Rcd9imbdndnaLcl0mbdnaOJbbbZMgO:lJbbb9p9DTmbaO:Ohixdkcjjjj94hixekaPaCfcd9Thika5aQaeEhQaLcefgLcs9hmekkdndnaXmbcihicbhDxekawakcbyd;y:L:cjbHjjjjbbg8ABdKawclBd2aPcuf:YhYdnadTmbaqhiaxheadhKindndnaiIdbaYNJbbbZMgO:lJbbb9p9DTmbaO:OhExekcjjjj94hEkaEcCthEdndnaiclfIdbaYNJbbbZMgO:lJbbb9p9DTmbaO:Oh3xekcjjjj94h3ka3cqtaEVhEdndnaicwfIdbaYNJbbbZMgO:lJbbb9p9DTmbaO:Oh3xekcjjjj94h3kaeaEa3VBdbaicxfhiaeclfheaKcufgKmbkkawcuazama8Aaxadz:mjjjbgDc32giaDc;j:KM;jb0Ecbyd;y:L:cjbHjjjjbbgeBd3awcvBd2aecbaiz:xjjjbh3avcd4hxdnadTmbdnalTmbaxcdth8Ea8AhEaqhealhKadhAina3aEydbc32fgiaeIdbaiIdbMUdbaiaeclfIdbaiIdlMUdlaiaecwfIdbaiIdwMUdwaiaKIdbaiIdxMUdxaiaKclfIdbaiIdzMUdzaiaKcwfIdbaiIdCMUdCaiaiIdKJbbjZMUdKaEclfhEaecxfheaKa8EfhKaAcufgAmbxdkka8AhKaqheadhEina3aKydbc32fgiaeIdbaiIdbMUdbaiaeclfIdbaiIdlMUdlaiaecwfIdbaiIdwMUdwaiaiIdxJbbbbMUdxaiaiIdzJbbbbMUdzaiaiIdCJbbbbMUdCaiaiIdKJbbjZMUdKaKclfhKaecxfheaEcufgEmbkkdnaDTmba3hiaDheinaiaiIdbJbbbbJbbjZaicKfIdbgO:vaOJbbbb9BEgONUdbaiclfgKaOaKIdbNUdbaicwfgKaOaKIdbNUdbaicxfgKaOaKIdbNUdbaiczfgKaOaKIdbNUdbaicCfgKaOaKIdbNUdbaic3fhiaecufgembkkcbhEawcuaDcdtgCaDcFFFFi0Egicbyd;y:L:cjbHjjjjbbgeBdaawcoBd2awaicbyd;y:L:cjbHjjjjbbg8EBd8KaecFeaCz:xjjjbh5dnadTmbaoJbbjZJbbjZaY:vaPceSENgOaONhYaxcdthxalheinaYaecN:H:cjbalEgKIdwa3a8AydbgAc32fgiIdC:tgOaONaKIdbaiIdx:tgOaONaKIdlaiIdz:tgOaONMMNaqcwfIdbaiIdw:tgOaONaqIdbaiIdb:tgOaONaqclfIdbaiIdl:tgOaONMMMhOdndna5aAcdtgifgKydbcuSmba8EaifIdbaO9ETmekaKaEBdba8EaifaOUdbka8Aclfh8AaqcxfhqaeaxfheadaEcefgE9hmbkkaba5aCz:wjjjb8Acrhikaicdthiawcxfc98fheinaeaifydbcbyd;C:L:cjbH:bjjjbbaic98fgimbkkawc;Wbf8KjjjjbaDk:Pdidui99ducbhi8Jjjjjbca9Rglcbyd1:G:cjbBdKalcb8Pdj:G:cjb83izalcbydN:G:cjbBdwalcb8Pd:m:G:cjb83ibdndnaembJbbjFhvJbbjFhoJbbjFhrxekadcd4cdthwincbhdinalczfadfgDabadfIdbgvaDIdbgoaoav9EEUdbaladfgDavaDIdbgoaoav9DEUdbadclfgdcx9hmbkabawfhbaicefgiae9hmbkalIdwalIdK:thralIdlalIdC:thoalIdbalIdz:thvkJbbbbavavJbbbb9DEgvaoaoav9DEgvararav9DEk:H8Modui99lud99Aus998Jjjjjbcji9RgD8KjjjjbcbhqaDcxfcbc;Kbz:xjjjb8AaDcbBdwaD9cb83ibaDcbyd;i:L:cjbBd1eaDcb8Pd;a:L:cjb83ijeaDcbyd;u:L:cjbBd94aDcb8Pd;m:L:cjb83i9WdndnavmbJbbjFhkJbbjFhxJbbjFhmxekaocd4cdthPalhsincbhzinaDcjefazfgHasazfIdbgkaHIdbgxaxak9EEUdbaDc;WbfazfgHakaHIdbgxaxak9DEUdbazclfgzcx9hmbkasaPfhsaqcefgqav9hmbkaDId94aDId1e:thmaDIdtaDId:ee:thxaDId9WaDIdje:thkkJbbbbhOdnar:YgAJq;x8J88MaA:vJbbbbakakJbbbb9DEgkaxaxak9DEgkamamak9DENgxJbbbb9Bmbarc9:f:Yax:vhOkaDcCfhCaDcxfcxfhXcbhzinaDazfaDcjefazfIdbgkaxaDc;WbfazfIdbak:t:tJbbb:;NMUdbazclfgzcx9hmbkcbhQaDarar2gLar2gzcbyd;y:L:cjbHjjjjbbgHBdxaDceBd2aHcbazz:xjjjbgKcbcbadaialaoaraOaDawz:rjjjbcdhYaDcuaLcdtaLcFFFFi0Eg8Acbyd;y:L:cjbHjjjjbbgEBdzaDcdBd2aDcjefcbarz:xjjjb8Acbh3dnaLTmbdnarcb9kmbaKhzaEhHaLhsincbh3aHcbcuazaDcjefarz:AjjjbEBdbazarfhzaHclfhHascufgsmbxdkkaKhPcbh3cbhvindndnaKavar2faDcjefarz:AjjjbTmbcbhHaPhzarhsinazaHazRbbgqfgHcbaqE86bbazcefhzascufgsmbkaEavcdtfa3BdbaHa3fh3xekaEavcdtfcuBdbkaParfhPavcefgvaL9hmbkkdnabTmbaDcua3cotgza3cFFF8F0Ecbyd;y:L:cjbHjjjjbbgQBdCcihYaDciBd2aQcbazz:xjjjb8AaXhCkdnawceGmbaCa8Acbyd;y:L:cjbHjjjjbbg5BdbaDaYcefgzBd2aDcxfazcdtfaLcbyd;y:L:cjbHjjjjbbgzBdbaDaYcdfgYBd2azcbaLz:xjjjbh8EarcufhXdnarci9imbarc9:fhCararcef2aKfcefh8Aceh8Fina8Far2hPa8AhvcehqindnaEaqaPfcdtfydbcuSmbavhzaChHinazazRbbgscuasE86bbazcefhzaHcufgHmbkkavarfhvaqcefgqaX9hmbka8AaLfh8Aa8Fcefg8FaX9hmbkkarce9imbcbh8Acbhqcbhvina8EaqfhscbhzindnasazfgHRbbmbaHce86bba5a8AcdtfaqazfBdba8Acefh8Akarazcefgz9hmbkaqarfhqavcefgvar9hmbka8ATmbaKcefhaaKc9:fhharc9:fhgarci9ih8Jina8Ea5a8Acufg8Acdtfydbgvfcb86bbavar2hPdna8JmbaEavcdtfydbcuSmbaKaPfhHaghqindnaHcefgzRbbgscFe9hmbaHRbbmbcbhskazas86bbazhHaqcufgqmbkaharavcef2fhzaXhsindnazRbbgHcFe9hmbazcefRbbmbcbhHkazaH86bbazcufhzascufgsce9kmbkkaaaPfh8Kavavar9Ug8Lar29Rh8FcbhCindnaCceScuaCEa8Ffgzce9imbazaX9ombcuaCciSaCcdSEa8LfgHce9imbaHaX9ombaEaHar2azfg8McdtfydbcuSmba8Jmbaaa8Mar2fhzcbhqa8KhsaghvinazazRbbgHcbaHaHcFeSEasRbbEgP86bbascefhsazcefhzaPaH7aqVhqavcufgvmbkaqcFeGTmba8Ea8MfgzRbbmbazce86bba5a8Acdtfa8MBdba8Acefh8AkaCcefgCcl9hmbka8AmbkkdnaQTmbaKaEaQadaialaoaraOaDawz:rjjjba3TmbJbbjZaO:vhkawcjjjjlGhPdnawcdGTmbJbbnnaOaON:vh8NakJbbbZNhyaQhzinazczfgsIdbg8PazcCfIdbgx:vhmazcxfgqIdbgIax:vhAazcwfgvIdbg8Rax:vh8SakazydbgHcFrG:ZNhRakaHcq4cFrG:ZNh8UakaHcC4cFrG:ZNh8VdnaxJ:p;c;188Ng8WazcKfIdbMg8X:laxJ:983:g81Ngx9ETmba8Wazc3fIdbMazc8KfIdbg8Ya8Ya8X:vg8YN:tg8Z:lax9ETmba8WazcafIdbMazcyfIdbg8Wa8Wa8X:vg80N:tazc8SfIdba8Wa8YN:tg8Wa8Wa8Z:vg8WN:tg81:lax9ETmba8PJ:p;c;188NazcUfIdb:ta80a8RJ:p;c;188Nazc8WfIdb:tg8PN:ta8WaIJ:p;c;188Nazc80fIdb:ta8Ya8PN:tgIN:ta81:vgxam:tg8Ra8RNa8Pa8X:va8YaIa8Z:va8WaxN:tg8XN:ta80axN:tg8Wa8S:tg8Ya8YNa8XaA:tg8Ya8YNMMa8N9DTmbaxaRaxaR9EEgxakaRMgmaxam9DEhma8Xa8Ua8Xa8U9EEgxaka8UMgAaxaA9DEhAa8Wa8Va8Wa8V9EEgxaka8VMg8Saxa8S9DEh8SkdnaPTmbayaRMhmaya8UMhAaya8VMh8SkasamUdbaqaAUdbava8SUdbazc;abfhza3cufg3mbxdkkdnaPTmbakJbbbZNhxaQhzinazczfaxakazydbgHcFrG:ZNMUdbazcxfaxakaHcq4cFrG:ZNMUdbazcwfaxakaHcC4cFrG:ZNMUdbazc;abfhza3cufg3mbxdkkaQcCfhzinazc98fgHaHIdbazIdbgk:vUdbazc94fgHaHIdbak:vUdbazctfgHaHIdbak:vUdbazc;abfhza3cufg3mbkkcbhsdndnarcd9imbarcufh3aEarcdtfhadnabmbaKcefg8Mararcefgz2fh8JaKazfhba8MaLfh8Ecbhscbh8Kina8Kar2h8La8Mheabh8Aa8Eh8Fa8Jh5cbhXindnaEaXa8LfgqcdtgzfgHclfydbaHydbGaaazfgzydbGazclfydbGcuSmbclcbaKaqar2fgzarfRbbEazRbbcb9hVczcbazaLfgzRbbEVc;abcbazarfRbbEVhPaehza8AhHa8Fhqa5hva3hQindnaPclcbaHRbbEazRbbcb9hVczcbaqRbbEVc;abcbavRbbEVgPcetVgCTmbaCcFeSmbasaCRb;W;p:cjbfhskazcefhzaHcefhHaqcefhqavcefhvaQcufgQmbkkaearfhea8Aarfh8Aa8Farfh8Fa5arfh5aXcefgXa39hmbka8MaLfh8MabaLfhba8EaLfh8Ea8JaLfh8Ja8Kcefg8Ka39hmbxdkkJbbjZaO:vgkakJk;x8J88NNh8RawcdGh8EaDIdwhkaDIdlhxaDIdbhmcbhscbhPinaPar2h8KcbhvindnaEava8KfgqcdtgzfgHclfydbaHydbGaaazfgzydbGazclfydbGcuSmbcbh8AclcbaKaqar2fgYarfRbbEaYRbbcb9hVczcbaYaLfg8JRbbEVc;abcba8JarfRbbEVh8Lindna8LclcbaYa8Ag8Mcefg8AfgzarfRbbEazRbbcb9hVczcba8Ja8AfgzRbbEVc;abcbazarfRbbEVg8LcetVgCTmbaCcFeSmbcbhqdndndnaCRb;W;n:cjbcufPdebdka8ETmeaCcC2gz8Ve;W:L:cjbcltaz8Ve;Y:L:cjbcsGVh8FaKa8Mfh5cxhzaDcjefhHinaHaQaEa8Faz4gqce4ceGavfaqcd4ceGaPfar2fgXcdtfydbcotfa5aqceGfaXar2fRbbcotfcnfBdbaHclfhHazc98fgzc989hmbkaDydjegzIdyaDyd:megHIdyMaDyd:eegqIdyaDyd1egXIdyMMg8XaqIdwaXIdwMJbbbZNgANazIdUaHIdUMaqIdUaXIdUMMg8WMg8Sa8SMazIdaaHIdaMaqIdaaXIdaMMg8YaqIdzaXIdzMJbbbZNg8SNMa8SNazId8SaHId8SMaqId8SaXId8SMMgRa8SNazId80aHId80MaqId80aXId80MMg8UMg8Sa8SMazId3aHId3MaqId3aXId3MMg8VaqIdxaXIdxMJbbbZNg8SNMa8SNazId8KaHId8KMaqId8KaXId8KMMg8Za8SNazId8WaHId8WMaqId8WaXId8WMMg80Mg8Sa8SMazIdKaHIdKMaqIdKaXIdKMMgyaANMaANazId88aHId88MaqId88aXId88MMg8PMMM:lgIa8RazIdCaHIdCMaqIdCaXIdCMMN9Ea8XazIdwaHIdwMJbbbZNgANa8WMg8Sa8SMa8YazIdzaHIdzMJbbbZNg8SNMa8SNaRa8SNa8UMg8Sa8SMa8VazIdxaHIdxMJbbbZNg8SNMa8SNa8Za8SNa80Mg8Sa8SMayaANMaANa8PMMM:laIJ;d;1UZN9DGhqxekaKa8Mfh8FcbhzcrhHindnaCaz4ceGTmba8FazceGfazce4ceGavfazcd4aPfar2fgqar2fRbbgXcFeSmbaQaEaqcdtfydbcotfaXcotfc9efRbbaH4ceGTmbcbhqxdkaHcufhHcehqazcefgzcw9hmbkkaCcC2aqcq2fgH8Ve;W:L:cjbgzTmbaHc;Y:L:cjbfhqaKa8MfhCabasc8K2fhHindnasae9pmbaHaQaEazcD4ceGavfazcq4ceGaPfar2fgXcdtfydbcotfaCazcw4ceGfaXar2fRbbcotfgXc9ifIdbamMUdbaHclfaXc9mfIdbaxMUdbaHcwfaXc9qfIdbakMUdbaHcxfamaQaEazcv4ceGavfazco4ceGaPfar2fgXcdtfydbcotfaCazcl4ceGfaXar2fRbbcotfgXc9ifIdbMUdbaHczfaxaXc9mfIdbMUdbaHcCfakaXc9qfIdbMUdbaHcKfamaQaEazce4ceGavfazcd4ceGaPfar2fgXcdtfydbcotfaCazceGfaXar2fRbbcotfgzc9ifIdbMUdbaHc3faxazc9mfIdbMUdbaHcafakazc9qfIdbMUdbkaHc8KfhHascefhsaq8Vebhzaqcdfhqazmbkka8Aa39hmbkkavcefgva39hmbkaPcefgPa39hmbkaDyd2gYTmekaYcdtaDcxffc98fhzinazydbcbyd;C:L:cjbH:bjjjbbazc98fhzaYcufgYmbkkaDcjif8Kjjjjbask;Kxmiue99due99euz99eui99eud99dud99oudnalTmbaocd4hkaqcdGhxarc99fhqarcethmawawMhPcbhsindndnawavaiascdtfgoclfydbak2cdtfgzIdwgHavaoydbak2cdtfgOIdwgA:tgCaCNazIdbgXaOIdbgQ:tgLaLNazIdlgKaOIdlgY:tg8Aa8ANMMgEavaocwfydbak2cdtfgoIdwg3aA:tg5a5NaoIdbg8EaQ:tg8Fa8FNaoIdlgaaY:tghahNMMggaEag9EEgEa3aH:tgHaHNa8EaX:tgHaHNaaaK:tgHaHNMMgHaEaH9EE:rNgHaHMgH:lJbbb9p9DTmbaH:Ohoxekcjjjj94hokdnaLahNa8Aa8FN:tgHaHNa8Aa5NaCahN:tgXaXNaCa8FNaLa5N:tgKaKNMMg3Jbbbb9BmbJbbjZhEdnaoceaoce9kEgoamaoam9iEg8Jcd9imbJbbjZa8J:Z:vhEkarcb9imbaAaDIdw:th8KaYaDIdl:th8LaQaDIdb:th8Ma8Jcba8Jcb9kEh8NdnadTmbaHJbbjZa3:rgA:vgQNg3aAa8Jcefa8Jcdf2:Y:vgANh8EaKaQNgKaANhyaXaQNgXaXaANNh8PcbhIina8Jcba8Jcb9kEcefh8RaEaI:ZNgQaCNa8KMhgaQa8ANa8LMh8SaQaLNa8MMhRcbhzindndnaPaEaz:ZNgQahNa8SMgYNgH:lJbbb9p9DTmbaH:OhOxekcjjjj94hOkaOce91goaqaoaq6Eh8UdndnaPaQa5NagMgHNga:lJbbb9p9DTmbaa:Oh8Vxekcjjjj94h8Vka8Ua8Vce91goaqaoaq6Eg8Wcefar2fcefgoar2h8XdndnaPaQa8FNaRMgQNga:lJbbb9p9DTmbaa:Oh8Yxekcjjjj94h8Ykadaeaocdtfydbcotfaba8Yce91goaqaoaq6Eg8Zfa8XfcefRbbcotfgocnfa8Ucqta8ZcCtVa8WVBdbaoc9efg8Ua8URbbcea8YceGaOcetcdGVa8VcdtclGVtV86bbaoc9ifgOaQaANaOIdbMUdbaoc9mfgOaYaANaOIdbMUdbaoc9qfgOaHaANaOIdbMUdbaoc9ufgOaAaOIdbMUdbdnaxTmbaoc9yfgOa8PaOIdbMUdbaoc9CfgOaKayNaOIdbMUdbaoc9GfgOa3a8ENaOIdbMUdbaoc9KfgOaXayNaOIdbMUdbaoc9OfgOaXa8ENaOIdbMUdbaoc2fgOaKa8ENaOIdbMUdbaoc9WfgOaXaAa3aHNaXaQNaKaYNMMgY:mNgQNaOIdbMUdbaoctfgOaKaQNaOIdbMUdbaoc94fgOa3aQNaOIdbMUdbaoc98fgoaoIdbaYaQN:tUdbka8Razcefgz9hmbka8Jcufh8JaIa8NShoaIcefhIaoTmbxdkkcbh8Vina8Jcba8Jcb9kEcefh8UaEa8V:ZNgAaCNa8KMhYaAa8ANa8LMhHaAaLNa8MMhXcbhoindndnaPaEao:ZNgAahNaHMNgQ:lJbbb9p9DTmbaQ:Ohzxekcjjjj94hzkazce91gzaqazaq6EhzdndnaPaAa5NaYMNgQ:lJbbb9p9DTmbaQ:OhOxekcjjjj94hOkazaOce91gOaqaOaq6Ecefar2fcefar2hzdndnaPaAa8FNaXMNgA:lJbbb9p9DTmbaA:OhOxekcjjjj94hOkabaOce91gOaqaOaq6Efazfcefce86bba8Uaocefgo9hmbka8Jcufh8Ja8Va8NShoa8Vcefh8VaoTmbkkascifgsal6mbkkk:Nvezu8Jjjjjbcjd9Rgb8Kjjjjbcbheabcbcjdz:xjjjbhdc:W:H:cjbhbinabRbbgicC2glabcqf8Veb87e;4:L:cjbalabcdfgv8Peb83e;W:L:cjbaiabcefRbb86b;W;n:cjbadaifce86bbalavabcxfceaetc:F:d;avGEgi8Peb83e;6:L:cjbalai8Vew87e:c:M:cjbabcQfhbaecefgecK9hmbkcbhoinc;Y:L:cjbhrcbhvindnadavfgwRbbce9hmbavcC2c;W:L:cjbfhDcbhbcehqavc;W;n:cjbfhkinabcitc:G:H:cjbfhlcbhbcbheinaeavab4ceGalabfRbbtVheabcefgbcw9hmbkdnadaecFeGgxfgmRbbmbaxcC2c;W:L:cjbfhPcbhbcehsindnaDabcq2gif8VebgbTmbaraifheaPaifhiinaialabcl4csGfRbbcltalabcw4csGfRbbcwtValabcsGfRbbV87ebaicdfhiae8VebhbaecdfheabmbkkcehbasceGhecbhsaembkamce86bbaxakRbb86b;W;n:cjbkcehbaqceGhlcbhqalmbkawcd86bbkarcCfhravcefgvcjd9hmbkaocefgoci9hmbkcbhic;W:L:cjbhvincuhlavhbinalcefhlab8Vebheabcdfhbaembkaial86b;W;p:cjbavcCfhvaicefgicjd9hmbkadcjdf8Kjjjjbk9DeeuabcFeaicdtz:xjjjbhlcbhbdnadTmbindnalaeydbcdtfgiydbcu9hmbaiabBdbabcefhbkaeclfheadcufgdmbkkabk;Bidqui998Jjjjjbc;Wb9Rgl8Kjjjjbalcxfcbc;Kbz:xjjjb8Aadcd4adfhvcehoinaogrcethoarav6mbkalcuarcdtgoarcFFFFi0Ecbyd;y:L:cjbHjjjjbbgvBdxavcFeaoz:xjjjbhwdnadTmbaicd4hDarcufhqcbhkindndnawcbaeakaD2cdtfgrydlgiaicjjjj94SEgocH4ao7c:F:b:DD2cbarydbgxaxcjjjj94SEgocH4ao7c;D;O:B8J27cbarydwgmamcjjjj94SEgrcH4ar7c:3F;N8N27aqGgvcdtfgrydbgocuSmbam::hPai::hsax::hzcehiinaihrdnaeaoaD2cdtfgiIdbaz9CmbaiIdlas9CmbaiIdwaP9BmikarcefhiawavarfaqGgvcdtfgrydbgocu9hmbkkarakBdbakhokabakcdtfaoBdbakcefgkad9hmbkkalydxcbyd;C:L:cjbH:bjjjbbalc;Wbf8Kjjjjbk9teiucbcbyd;G:L:cjbgeabcifc98GfgbBd;G:L:cjbdndnabZbcztgd9nmbcuhiabad9RcFFifcz4nbcuSmekaehikaik;LeeeudndnaeabVciGTmbabhixekdndnadcz9pmbabhixekabhiinaiaeydbBdbaiclfaeclfydbBdbaicwfaecwfydbBdbaicxfaecxfydbBdbaeczfheaiczfhiadc9Wfgdcs0mbkkadcl6mbinaiaeydbBdbaeclfheaiclfhiadc98fgdci0mbkkdnadTmbinaiaeRbb86bbaicefhiaecefheadcufgdmbkkabk;aeedudndnabciGTmbabhixekaecFeGc:b:c:ew2hldndnadcz9pmbabhixekabhiinaialBdbaicxfalBdbaicwfalBdbaiclfalBdbaiczfhiadc9Wfgdcs0mbkkadcl6mbinaialBdbaiclfhiadc98fgdci0mbkkdnadTmbinaiae86bbaicefhiadcufgdmbkkabk9teiucbcbyd;G:L:cjbgeabcrfc94GfgbBd;G:L:cjbdndnabZbcztgd9nmbcuhiabad9RcFFifcz4nbcuSmekaehikaikTeeucbabcbyd;G:L:cjbge9Rcifc98GaefgbBd;G:L:cjbdnabZbcztge9nmbabae9RcFFifcz4nb8Akk6eiucbhidnadTmbdninabRbbglaeRbbgv9hmeaecefheabcefhbadcufgdmbxdkkalav9Rhikaikk;0vdbcj:Gdk;yvFFuuFFuuFFuuFFuFFFuFFFuFbbbbbbbbebbbdbbbbbbbebbbebbbdbbbbbbbbbbbeeeeeebebbeebbebbebbbeeebbbbebbbbbbbbbbbbbbbbbbbeeeeeeebebbbeeebbeebbbbbebbbbbebebbbbbbbbbbbbbbbdiorbelvlbodveribbbbbbbbbbbbbbbbbbbbbbebbbbbbbbbbbbbbbbbbbbbibbbbbbbbbbbbbbbbbbbbbobbbbbbbbbbbbbbbbbbbbbrbaebbbbbbbbbbbbbbbbbbsd8We8YbbbbbbbhiaebbbbbbQe8Ke9cebbbbbbbbbbbbbbbbLb8KebbbbbbbbbbbbbbbbbbKbbbbbbbbbbbbbbbbbbbbbYeJbilbbbbbbbbbbbbbbbbEe80e8WlbbbbbbzlAbbbbbbb5eJdnibbbbbbai8Kbbbbbbb8Ee9ce8Ylcibbbb8Yebbbbbbbb8FdOlAdbbbbbb80e8Ylbbbbbb88eTi8KiJv8Jlbbbbbbbbbbbb89e9td8Kv9qibbbbndlvaibbbbZd8Li8KvbbbbbbJdTibbbbbb9Pe81b9GvoiBvbbbbbbbbbbbb9Re9JbvoWibbbbvibbbbbbbb9VeWi9Gvbbbbbb8WvBbbbbbbb9:b9ceBvbbbbbbbbbbbbbbbbubWibbbbbbbbbbbbbbbbbb;Wd9hvSrbbbbbbWl9NvbbbbbbFbbbbbbbbbbbbbbbbbbbbbFFuuFFuuFFuuFFuFFFuFFFuFbc;y:Ldkxebbbdbbb;W:Obb",e=new Uint8Array([32,0,65,2,1,106,34,33,3,128,11,4,13,64,6,253,10,7,15,116,127,5,8,12,40,16,19,54,20,9,27,255,113,17,42,67,24,23,146,148,18,14,22,45,70,69,56,114,101,21,25,63,75,136,108,28,118,29,73,115]);if(typeof WebAssembly!="object")return{supported:!1};var t,a=WebAssembly.instantiate(i(n),{}).then(function(v){t=v.instance,t.exports.__wasm_call_ctors()});function i(v){for(var E=new Uint8Array(v.length),_=0;_<v.length;++_){var A=v.charCodeAt(_);E[_]=A>96?A-97:A>64?A-39:A+4}for(var k=0,_=0;_<v.length;++_)E[k++]=E[_]<60?e[E[_]]:(E[_]-60)*64+E[++_];return E.buffer.slice(0,k)}function r(v){if(!v)throw new Error("Assertion failed")}function s(v){return new Uint8Array(v.buffer,v.byteOffset,v.byteLength)}function o(v,E,_,A){var k=t.exports.sbrk,w=k(_*4),M=k(_*A*4),R=new Uint8Array(t.exports.memory.buffer);R.set(s(E),M),v(w,M,_,A*4),R=new Uint8Array(t.exports.memory.buffer);var U=new Uint32Array(_);return new Uint8Array(U.buffer).set(R.subarray(w,w+_*4)),k(w-k(0)),U}function c(v,E,_){var A=t.exports.sbrk,k=A(E.length*4),w=A(_*4),M=new Uint8Array(t.exports.memory.buffer),R=s(E);M.set(R,k);var U=v(w,k,E.length,_);M=new Uint8Array(t.exports.memory.buffer);var P=new Uint32Array(_);new Uint8Array(P.buffer).set(M.subarray(w,w+_*4)),A(k-A(0));for(var D=0;D<E.length;++D)E[D]=P[E[D]];return[P,U]}function l(v){for(var E=0,_=0;_<v.length;++_){var A=v[_];E=E<A?A:E}return E}function h(v,E,_,A,k,w,M,R,U){var P=t.exports.sbrk,D=P(4),V=P(_*4),B=P(k*w),G=P(_*4),z=new Uint8Array(t.exports.memory.buffer);z.set(s(A),B),z.set(s(E),G);var Y=v(V,G,_,B,k,w,M,R,U,D);z=new Uint8Array(t.exports.memory.buffer);var te=new Uint32Array(Y);s(te).set(z.subarray(V,V+Y*4));var ie=new Float32Array(1);return s(ie).set(z.subarray(D,D+4)),P(D-P(0)),[te,ie[0]]}function d(v,E,_,A,k,w,M,R,U,P,D,V,B){var G=t.exports.sbrk,z=G(4),Y=G(_*4),te=G(k*w),ie=G(k*R),pe=G(U.length*4),Te=G(_*4),W=P?G(k):0,J=new Uint8Array(t.exports.memory.buffer);J.set(s(A),te),J.set(s(M),ie),J.set(s(U),pe),J.set(s(E),Te),P&&J.set(s(P),W);var se=v(Y,Te,_,te,k,w,ie,R,pe,U.length,W,D,V,B,z);J=new Uint8Array(t.exports.memory.buffer);var re=new Uint32Array(se);s(re).set(J.subarray(Y,Y+se*4));var ge=new Float32Array(1);return s(ge).set(J.subarray(z,z+4)),G(z-G(0)),[re,ge[0]]}function f(v,E,_,A,k,w,M,R,U,P,D,V,B){var G=t.exports.sbrk,z=G(4),Y=G(k*w),te=G(k*R),ie=G(U.length*4),pe=G(_*4),Te=P?G(k):0,W=new Uint8Array(t.exports.memory.buffer);W.set(s(A),Y),W.set(s(M),te),W.set(s(U),ie),W.set(s(E),pe),P&&W.set(s(P),Te);var J=v(pe,_,Y,k,w,te,R,ie,U.length,Te,D,V,B,z);W=new Uint8Array(t.exports.memory.buffer),s(E).set(W.subarray(pe,pe+J*4)),s(A).set(W.subarray(Y,Y+k*w)),s(M).set(W.subarray(te,te+k*R));var se=new Float32Array(1);return s(se).set(W.subarray(z,z+4)),G(z-G(0)),[J,se[0]]}function b(v,E,_,A){var k=t.exports.sbrk,w=k(_*A),M=new Uint8Array(t.exports.memory.buffer);M.set(s(E),w);var R=v(w,_,A);return k(w-k(0)),R}function p(v,E,_,A,k,w,M,R){var U=t.exports.sbrk,P=U(R*4),D=U(_*A),V=k?U(_*w):0,B=new Uint8Array(t.exports.memory.buffer);B.set(s(E),D),k&&B.set(s(k),V);var G=v(P,D,_,A,V,w,M,R);B=new Uint8Array(t.exports.memory.buffer);var z=new Uint32Array(G);return s(z).set(B.subarray(P,P+G*4)),U(P-U(0)),z}function g(v,E,_,A,k,w,M,R,U){var P=t.exports.sbrk,D=P(4),V=P(_*4),B=P(k*w),G=P(_*4),z=M?P(k):0,Y=new Uint8Array(t.exports.memory.buffer);Y.set(s(A),B),Y.set(s(E),G),M&&Y.set(s(M),z);var te=v(V,G,_,B,k,w,z,R,U,D);Y=new Uint8Array(t.exports.memory.buffer);var ie=new Uint32Array(te);s(ie).set(Y.subarray(V,V+te*4));var pe=new Float32Array(1);return s(pe).set(Y.subarray(D,D+4)),P(D-P(0)),[ie,pe[0]]}function m(v,E,_,A,k,w,M){var R=t.exports.sbrk,U=R(_*4),P=R(k*w),D=R(_*4),V=new Uint8Array(t.exports.memory.buffer);V.set(s(A),P),V.set(s(E),D);var B=v(U,D,_,P,k,w,M);V=new Uint8Array(t.exports.memory.buffer);var G=new Uint32Array(B);return s(G).set(V.subarray(U,U+B*4)),R(U-R(0)),G}function u(v,E,_,A,k,w){var M=t.exports.sbrk,R=M(_.byteLength),U=M(E.byteLength),P=new Uint8Array(t.exports.memory.buffer);P.set(s(_),R),P.set(s(E),U);var D=_.byteLength/A,V=v(0,0,U,E.length,R,D,A,k,w),B=M(V*9*4),G=v(B,V,U,E.length,R,D,A,k,w);r(G<=V),P=new Uint8Array(t.exports.memory.buffer);var z=new Float32Array(G*9);return s(z).set(P.subarray(B,B+z.byteLength)),M(R-M(0)),z}var y={LockBorder:1,Sparse:2,ErrorAbsolute:4,Prune:8,Regularize:16,Permissive:32,RegularizeLight:64,PreserveFolds:128,ErrorClamped:256,_InternalDebug:1<<30},x={Shell:1,Solve:2,Thicken:0,_InternalDebug:1<<30};return{ready:a,supported:!0,compactMesh:function(v){r(v instanceof Uint32Array||v instanceof Int32Array||v instanceof Uint16Array||v instanceof Int16Array),r(v.length%3==0);var E=v.BYTES_PER_ELEMENT==4?v:new Uint32Array(v),_=c(t.exports.meshopt_optimizeVertexFetchRemap,E,l(v)+1);if(v!==E)for(var A=0;A<E.length;++A)v[A]=E[A];return _},generatePositionRemap:function(v,E){return r(v instanceof Float32Array),r(v.length%E==0),r(E>=3),o(t.exports.meshopt_generatePositionRemap,v,v.length/E,E)},simplify:function(v,E,_,A,k,w){r(v instanceof Uint32Array||v instanceof Int32Array||v instanceof Uint16Array||v instanceof Int16Array),r(v.length%3==0),r(E instanceof Float32Array),r(E.length%_==0),r(_>=3),r(A>=0&&A<=v.length),r(A%3==0),r(k>=0);for(var M=0,R=0;R<(w?w.length:0);++R)r(w[R]in y),M|=y[w[R]];var U=v.BYTES_PER_ELEMENT==4?v:new Uint32Array(v),P=h(t.exports.meshopt_simplify,U,v.length,E,E.length/_,_*4,A,k,M);return P[0]=v instanceof Uint32Array?P[0]:new v.constructor(P[0]),P},simplifyWithAttributes:function(v,E,_,A,k,w,M,R,U,P){r(v instanceof Uint32Array||v instanceof Int32Array||v instanceof Uint16Array||v instanceof Int16Array),r(v.length%3==0),r(E instanceof Float32Array),r(E.length%_==0),r(_>=3),r(A instanceof Float32Array),r(A.length==k*(E.length/_)),r(k>=0),r(M==null||M instanceof Uint8Array),r(M==null||M.length==E.length/_),r(R>=0&&R<=v.length),r(R%3==0),r(U>=0),r(Array.isArray(w)),r(k>=w.length),r(w.length<=32);for(var D=0;D<w.length;++D)r(w[D]>=0);for(var V=0,D=0;D<(P?P.length:0);++D)r(P[D]in y),V|=y[P[D]];var B=v.BYTES_PER_ELEMENT==4?v:new Uint32Array(v),G=d(t.exports.meshopt_simplifyWithAttributes,B,v.length,E,E.length/_,_*4,A,k*4,new Float32Array(w),M,R,U,V);return G[0]=v instanceof Uint32Array?G[0]:new v.constructor(G[0]),G},simplifyWithUpdate:function(v,E,_,A,k,w,M,R,U,P){r(v instanceof Uint32Array||v instanceof Int32Array||v instanceof Uint16Array||v instanceof Int16Array),r(v.length%3==0),r(E instanceof Float32Array),r(E.length%_==0),r(_>=3),r(A instanceof Float32Array),r(A.length==k*(E.length/_)),r(k>=0),r(M==null||M instanceof Uint8Array),r(M==null||M.length==E.length/_),r(R>=0&&R<=v.length),r(R%3==0),r(U>=0),r(Array.isArray(w)),r(k>=w.length),r(w.length<=32);for(var D=0;D<w.length;++D)r(w[D]>=0);for(var V=0,D=0;D<(P?P.length:0);++D)r(P[D]in y),V|=y[P[D]];var B=v.BYTES_PER_ELEMENT==4?v:new Uint32Array(v),G=f(t.exports.meshopt_simplifyWithUpdate,B,v.length,E,E.length/_,_*4,A,k*4,new Float32Array(w),M,R,U,V);if(v!==B)for(var D=0;D<G[0];++D)v[D]=B[D];return G},getScale:function(v,E){return r(v instanceof Float32Array),r(v.length%E==0),r(E>=3),b(t.exports.meshopt_simplifyScale,v,v.length/E,E*4)},simplifyPoints:function(v,E,_,A,k,w){return r(v instanceof Float32Array),r(v.length%E==0),r(E>=3),r(_>=0&&_<=v.length/E),A?(r(A instanceof Float32Array),r(A.length%k==0),r(k>=3),r(v.length/E==A.length/k),p(t.exports.meshopt_simplifyPoints,v,v.length/E,E*4,A,k*4,w||0,_)):p(t.exports.meshopt_simplifyPoints,v,v.length/E,E*4,void 0,0,0,_)},simplifySloppy:function(v,E,_,A,k,w){r(v instanceof Uint32Array||v instanceof Int32Array||v instanceof Uint16Array||v instanceof Int16Array),r(v.length%3==0),r(E instanceof Float32Array),r(E.length%_==0),r(_>=3),r(A==null||A instanceof Uint8Array),r(A==null||A.length==E.length/_),r(k>=0&&k<=v.length),r(k%3==0),r(w>=0);var M=v.BYTES_PER_ELEMENT==4?v:new Uint32Array(v),R=g(t.exports.meshopt_simplifySloppy,M,v.length,E,E.length/_,_*4,A,k,w);return R[0]=v instanceof Uint32Array?R[0]:new v.constructor(R[0]),R},simplifyPrune:function(v,E,_,A){r(v instanceof Uint32Array||v instanceof Int32Array||v instanceof Uint16Array||v instanceof Int16Array),r(v.length%3==0),r(E instanceof Float32Array),r(E.length%_==0),r(_>=3),r(A>=0);var k=v.BYTES_PER_ELEMENT==4?v:new Uint32Array(v),w=m(t.exports.meshopt_simplifyPrune,k,v.length,E,E.length/_,_*4,A);return w=v instanceof Uint32Array?w:new v.constructor(w),w},remesh:function(v,E,_,A,k){r(v instanceof Uint32Array||v instanceof Int32Array||v instanceof Uint16Array||v instanceof Int16Array),r(v.length%3==0),r(E instanceof Float32Array),r(E.length%_==0),r(_>=3),r(A>=4&&A<=256);for(var w=0,M=0;M<(k?k.length:0);++M)r(k[M]in x),w|=x[k[M]];var R=v.BYTES_PER_ELEMENT==4?v:new Uint32Array(v);return u(t.exports.meshopt_remesh,R,E,_*4,A,w)}}})();(function(){var n="b9H79Tebbbe:neP9Geueu9Geub9Gbb9Giuuueu9Gmuuuuuuuuuuu9999eu9Gouuuuuueu9Gruuuuuuub9Gxuuuuuuuuuuuueu9Gxuuuuuuuuuuu99eu9GPuuuuuuuuuuuuu99b9Gouuuuuub9Gwuuuuuuuub9Gvuuuuub9GluuuubiQXdilvorwDqokoqxmbiibeilve9Weiiviebeoweuecj:Gdkr;Zeqo9TW9T9VV95dbH9F9F939H79T9F9J9H229F9Jt9VV7bb8A9TW79O9V9Wt9F9I919P29K9nW79O2Wt79c9V919U9KbeY9TW79O9V9Wt9F9I919P29K9nW79O2Wt7S2W94bd39TW79O9V9Wt9F9I919P29K9nW79O2Wt79t9W9Ht9P9H2bo39TW79O9V9Wt9F9J9V9T9W91tWJ2917tWV9c9V919U9K7bw39TW79O9V9Wt9F9J9V9T9W91tW9nW79O2Wt9c9V919U9K7bkE9TW79O9V9Wt9F9J9V9T9W91tW9t9W9OWVW9c9V919U9K7bxL9TW79O9V9Wt9F9V9Wt9P9T9P96W9nW79O2WtbPl79IV9RbsDwebcekdOAq;W:leXdbkIbabaec9:fgefcufae9Ugeabci9Uadfcufad9Ugbaeab0Ek:88JDPue99eux99due99euo99iu8Jjjjjbc:WD9Rgm8KjjjjbdndnalmbcbhPxekamc:Cwfcbc;Kbz:rjjjb8AcuaocdtgsaocFFFFi0Ehzcbyd;0:G:cjbhHdndnalcb9imbaoal9nmbamazaHHjjjjbbgHBd:CwamceBd;8wamazcbyd;0:G:cjbHjjjjbbgOBd:GwamcdBd;8wamcualcdtalcFFFFi0Ecbyd;0:G:cjbHjjjjbbgABd:KwamciBd;8waihzalhsinaHazydbcdtfcbBdbazclfhzascufgsmbkaihzalhsinaHazydbcdtfgCaCydbcefBdbazclfhzascufgsmbkaihzalhCcbhXindnaHazydbcdtgQfgsydbcb9imbaOaQfaXBdbasasydbgQcjjjj94VBdbaQaXfhXkazclfhzaCcufgCmbkalci9UhLdnalci6mbcbhzaihsinascwfydbhCasclfydbhXaOasydbcdtfgQaQydbgQcefBdbaAaQcdtfazBdbaOaXcdtfgXaXydbgXcefBdbaAaXcdtfazBdbaOaCcdtfgCaCydbgCcefBdbaAaCcdtfazBdbascxfhsaLazcefgz9hmbkkaihzalhsindnaHazydbcdtgCfgXydbgQcu9kmbaXaQcFFFFrGgQBdbaOaCfgCaCydbaQ9RBdbkazclfhzascufgsmbxdkkamazaHHjjjjbbgHBd:CwamceBd;8wamazcbyd;0:G:cjbHjjjjbbgOBd:GwamcdBd;8wamcualcdtalcFFFFi0Ecbyd;0:G:cjbHjjjjbbgABd:KwamciBd;8waHcbasz:rjjjbhXaihzalhsinaXazydbcdtfgCaCydbcefBdbazclfhzascufgsmbkalci9UhLdnaoTmbcbhzaOhsaXhCaohQinasazBdbasclfhsaCydbazfhzaCclfhCaQcufgQmbkkdnalci6mbcbhzaihsinascwfydbhCasclfydbhQaOasydbcdtfgKaKydbgKcefBdbaAaKcdtfazBdbaOaQcdtfgQaQydbgQcefBdbaAaQcdtfazBdbaOaCcdtfgCaCydbgCcefBdbaAaCcdtfazBdbascxfhsaLazcefgz9hmbkkaoTmbcbhzaohsinaOazfgCaCydbaXazfydb9RBdbazclfhzascufgsmbkkamaLcbyd;0:G:cjbHjjjjbbgzBd:OwamclBd;8wazcbaLz:rjjjbhYamcuaLcK2alcjjjjd0Ecbyd;0:G:cjbHjjjjbbg8ABd:SwamcvBd;8wJbbbbhEdnalci6g3mbarcd4hKaihsa8AhzaLhrJbbbbh5inavasclfydbaK2cdtfgCIdlh8EavasydbaK2cdtfgXIdlhEavascwfydbaK2cdtfgQIdlh8FaCIdwhaaXIdwhhaQIdwhgazaCIdbg8JaXIdbg8KMaQIdbg8LMJbbnn:vUdbazclfaXIdlaCIdlMaQIdlMJbbnn:vUdbaQIdwh8MaCIdwh8NaXIdwhyazcxfa8EaE:tg8Eagah:tggNaaah:tgaa8FaE:tghN:tgEJbbbbJbbjZa8Ja8K:tg8FahNa8Ea8La8K:tg8KN:tghahNaEaENaaa8KNa8FagN:tgEaENMMg8K:rg8E:va8KJbbbb9BEg8KNUdbazczfaEa8KNUdbazcCfaha8KNUdbazcwfa8Maya8NMMJbbnn:vUdba5a8EMh5ascxfhsazcKfhzarcufgrmbka5aL:Z:vJbbbZNhEkamcuaLcdtalcFFFF970Ecbyd;0:G:cjbHjjjjbbgCBd:WwamcoBd;8waq:Zhhdna3mbcbhzaChsinasazBdbasclfhsaLazcefgz9hmbkkaEahNhhamcuaLcltalcFFFFd0Ecbyd;0:G:cjbHjjjjbbg8PBd:0wamcrBd;8wcba8Pa8AaCaLcbz:djjjb8AJFFuuh8MJFFuuh8NJFFuuhydnalci6mbJFFuuhya8AhzaLhsJFFuuh8NJFFuuh8MinazcwfIdbgEa8Ma8MaE9EEh8MazclfIdbgEa8Na8NaE9EEh8NazIdbgEayayaE9EEhyazcKfhzascufgsmbkkah:rhEamaocetgzcuaocu9kEcbyd;0:G:cjbHjjjjbbgCBd:4wdndnaoal9nmbaihzalhsinaCazydbcetfcFFi87ebazclfhzascufgsmbxdkkaCcFeazz:rjjjb8AkaEJbbbZNh8JcuhIdnalci6mbcbhsJFFuuhEa8AhzcuhIinazcwfIdba8M:tghahNazIdbay:tghahNazclfIdba8N:tghahNMM:rghaEaIcuSahaE9DVgXEhEasaIaXEhIazcKfhzaLascefgs9hmbkkamczfcbcjwz:rjjjb8Aam9cb83iwam9cb83ibaxa8JNh8RJbbjZak:th8Lcbh8SJbbbbhRJbbbbh8UJbbbbh8VJbbbbh8WJbbbbh8XJbbbbh8Ycbh8ZcbhPinJbbbbhEdna8STmbJbbjZa8S:Z:vhEkJbbbbhhdna8Ya8YNa8Wa8WNa8Xa8XNMMg8KJbbbb9BmbJbbjZa8K:r:vhhka8VaENh8Ka8UaENh5aRaENh8EaIhLdndndndndna8SaPVTmbamydwg80Tmea8YahNh8Fa8XahNhaa8WahNhgaeamydbcdtfh81cbh3JFFuuhEcvhQcuhLindnaHa81a3cdtfydbcdtgzfydbgvTmbaAaOazfydbcdtfhsindndnaCaiasydbgKcx2fgzclfydbgrcetf8Vebcs4aCazydbgXcetf8Vebcs4faCazcwfydbglcetf8Vebcs4fgombcbhzxekcehzaHaXcdtfydbgXceSmbcehzaHarcdtfydbgrceSmbcehzaHalcdtfydbglceSmbdnarcdSaXcdSfalcdSfcd6mbaocefhzxekaocdfhzkdnazaQ9kmba8AaKcK2fgXIdwa8K:tghahNaXIdba8E:tghahNaXIdla5:tghahNMM:ra8J:va8LNJbbjZMJ9VO:d86JbbjZaXIdCa8FNaXIdxagNaaaXIdzNMMakN:tghahJ9VO:d869DENghaEazaQ6ahaE9DVgXEhEaKaLaXEhLazaQaXEhQkasclfhsavcufgvmbkka3cefg3a809hmbkkaLcu9hmekama8KUd:ODama5Ud:KDama8EUd:GDamcuBd:qDamcFFF;7rBdjDa8Pcba8AaYamc:GDfamc:qDfamcjDfz:ejjjbamyd:qDhLdndnaxJbbbb9ETmba8SaD6mbaLcuSmeceh3amIdjDa8R9EmixdkaLcu9hmekdna8STmbabaPcltfgHam8Piw83dwaHam8Pib83dbaPcefhPkc3hHinamc:CwfaHfydbcbyd;4:G:cjbH:bjjjbbaHc98fgHc989hmbxvkkcbh3a8Saq9pmbamydwaCaiaLcx2fgzydbcetf8Vebcs4aCazcwfydbcetf8Vebcs4faCazclfydbcetf8Vebcs4ffaw9nmekcbhzcbhsdna8ZTmbcbhsamczfhXinamczfascdtfaXydbgQBdbaXclfhXasaYaQfRbbTfhsa8Zcufg8ZmbkkamydwhlamydbhXam9cu83i:GDam9cu83i:ODam9cu83i:qDam9cu83i:yDinamcjDfazfcFFF;7rBdbazclfgzcz9hmbkasc;8easclfc:bd6Eg8Zcdth80dnalTmbaeaXcdtfhocbhrindnaHaoarcdtfydbcdtgzfydbgvTmbaAaOazfydbcdtfhscuhQcuhzinaHaiasydbgKcx2fgXclfydbcdtfydbaHaXydbcdtfydbfaHaXcwfydbcdtfydbfgXazaXaz6gXEhzaKaQaXEhQasclfhsavcufgvmbkaQcuSmba8AaQcK2fgsIdwa8M:tgEaENasIdbay:tgEaENasIdla8N:tgEaENMM:rhEcbhsindndnazamc:qDfasfgvydbgX6mbazaX9hmeaEamcjDfasfIdb9FTmekavazBdbamc:GDfasfaQBdbamcjDfasfaEUdbxdkasclfgscz9hmbkkarcefgral9hmbkkamczfa80fhQcbhzcbhsindnamc:GDfazfydbgXcuSmbaQascdtfaXBdbascefhskazclfgzcz9hmbkasa8Zfg8ZTmbJFFuuhhcuhKamczfhza8ZhvcuhQina8AazydbgXcK2fgsIdwa8M:tgEaENasIdbay:tgEaENasIdla8N:tgEaENMM:rhEdndnaHaiaXcx2fgsclfydbcdtfydbaHasydbcdtfydbfaHascwfydbcdtfydbfgsaQ6mbasaQ9hmeaEah9DTmekaEhhashQaXhKkazclfhzavcufgvmbkaKcuSmbaKhLkdnamaiaLcx2fgrydbarclfydbarcwfydbaCabaeadaPawaqa3z:fjjjbTmbaPcefhPJbbbbhRJbbbbh8UJbbbbh8VJbbbbh8WJbbbbh8XJbbbbh8YkcbhXinaAaOaraXcdtfydbcdtgsfydbcdtfgKhzaHasfgvydbgQhsdnaQTmbdninazydbaLSmeazclfhzascufgsTmdxbkkazaKaQcdtfc98fydbBdbavavydbcufBdbkaXcefgXci9hmbka8AaLcK2fgzIdbhEazIdlhhazIdwh8KazIdxh5azIdzh8EazIdCh8FaYaLfce86bba8Ya8FMh8Ya8Xa8EMh8Xa8Wa5Mh8Wa8Va8KMh8Va8UahMh8UaRaEMhRamydxh8Sxbkkamc:WDf8KjjjjbaPkjoivuv99lu8Jjjjjbca9Rgo8Kjjjjbdndnalcw0mbaiydbhraeabcitfgwalcdtciVBdlawarBdbdnalcd6mbaiclfhralcufhDawcxfhwinarydbhqawcuBdbawc98faqBdbawcwfhwarclfhraDcufgDmbkkalabfhwxekcbhqaocbBdKao9cb83izaocbBdwao9cb83ibJbbjZhkJbbjZhxinadaiaqcdtfydbcK2fhDcbhwinaoczfawfgraDawfIdbgmarIdbgP:tgsaxNaPMgPUdbaoawfgrasamaP:tNarIdbMUdbawclfgwcx9hmbkJbbjZakJbbjZMgk:vhxaqcefgqal9hmbkcbhradcbcecdaoIdlgmaoIdwgP9GEgwaoIdbgsaP9GEawasam9GEgzcdtgwfhHaoczfawfIdbhmaihwalhDinaiarcdtfgqydbhOaqawydbgABdbawaOBdbawclfhwaraHaAcK2fIdbam9DfhraDcufgDmbkdndnarcv6mbavc8X9kmbaralc98f6mekaiydbhraeabcitfgwalcdtciVBdlawarBdbaiclfhralcufhDawcxfhwinarydbhqawcuBdbawc98faqBdbawcwfhwarclfhraDcufgDmbkalabfhwxekaeabcitfgwamUdbawawydlc98GazVBdlabcefaeadaiaravcefgqz:djjjbhDawawydlciGaDabcu7fcdtVBdlaDaeadaiarcdtfalar9Raqz:djjjbhwkaocaf8Kjjjjbawk;Oddvue99dninabaecitfgrydlgwcd4gDTmednawciGgqci9hmbcihqdnawcl6mbabaecitfhbcbheawhqcehkindnaiabydbgDfRbbmbcbhkadaDcK2fgwIdwalIdw:tgxaxNawIdbalIdb:tgxaxNawIdlalIdl:tgxaxNMM:rgxaoIdb9DTmbaoaxUdbavaDBdbarydlhqkabcwfhbaecefgeaqcd46mbkakceGTmikaraqciGBdlskdnabcbaDalaqcdtfIdbarIdb:tgxJbbbb9FEgwaD7aecefgDfgecitfydlabawaDfgDcitfydlVci0mbaraqBdlkabaDadaialavaoz:ejjjbax:laoIdb9Fmbkkkjlevudndnabydwgxaladcetfgm8Vebcs4alaecetfgP8Vebgscs4falaicetfgz8Vebcs4ffaD0mbakmbcbhDabydxaq6mekavawcltfgxab8Pdw83dwaxab8Pdb83dbabydbhDdnabydwgwTmbaoaDcdtfhxawhsinalaxydbcetfcFFi87ebaxclfhxascufgsmbkkabaDawfBdbabydxhxab9cb83dwababydlaxci2fBdlaP8VebhscehDcbhxkdnascztcz91cu9kmbabaxcefBdwaPax87ebaoabydbcdtfaxcdtfaeBdbkdnam8Uebcu9kmbababydwgxcefBdwamax87ebaoabydbcdtfaxcdtfadBdbkdnaz8Uebcu9kmbababydwgxcefBdwazax87ebaoabydbcdtfaxcdtfaiBdbkarabydlfabydxci2faPRbb86bbarabydlfabydxci2fcefamRbb86bbarabydlfabydxci2fcdfazRbb86bbababydxcefBdxaDk:mPrHue99eue99eue99iu8Jjjjjbc;W;Gb9Rgx8KjjjjbdndnalmbcbhmxekcbhPaxc:m;Gbfcbc;Kbz:rjjjb8Aaxcualci9UgscltascjjjjiGEcbyd;0:G:cjbHjjjjbbgzBd:m9GaxceBd;S9GaxcuascK2gHcKfalcpFFFe0Ecbyd;0:G:cjbHjjjjbbgOBd:q9GaxcdBd;S9Gdnalci6gAmbarcd4hCascdthXaOhQazhLinavaiaPcx2fgrydwaC2cdtfhKavarydlaC2cdtfhYavarydbaC2cdtfh8AcbhraLhEinaQarfgma8Aarfg3Idbg5aYarfg8EIdbg8Fa5a8F9DEg5UdbamaKarfgaIdbg8Fa5a8Fa59DEg8FUdbamcxfgma3Idbg5a8EIdbgha5ah9EEg5UdbamaaIdbgha5aha59EEg5UdbaEa8Fa5MJbbbZNUdbaEaXfhEarclfgrcx9hmbkaQcKfhQaLclfhLaPcefgPas9hmbkkaOaHfgr9cb83dbar9cb83dzar9cb83dwaxcuascx2gralc:bjjjl0Ecbyd;0:G:cjbHjjjjbbgHBdN9GaxciBd;S9GascdthgazarfhvaxcwVhPaxclVhCaHh8Jazh8KcbhLinaxcbcj;Gbz:rjjjbhEaLas2cdthadnaAmba8Khrash3inaEarydbgmc8F91cjjjj94Vam7gmcQ4cx2fg8Ea8EydwcefBdwaEamcd4cFrGcx2fg8Ea8EydbcefBdbaEamcx4cFrGcx2fgmamydlcefBdlarclfhra3cufg3mbkkazaafh8AaHaafhXcbhmcbh3cbh8EcbhainaEamfgrydbhQara3BdbarcwfgKydbhYaKaaBdbarclfgrydbhKara8EBdbaQa3fh3aYaafhaaKa8Efh8Eamcxfgmcj;Gb9hmbkdnaAmbcbhravhminamarBdbamclfhmasarcefgr9hmbkavhrashminaEa8Aarydbg3cdtfydbg8Ec8F91a8E7cd4cFrGcx2fg8Ea8Eydbg8EcefBdbaXa8Ecdtfa3Bdbarclfhramcufgmmbka8JhrashminaCa8Aarydbg3cdtfydbg8Ec8F91a8E7cx4cFrGcx2fg8Ea8Eydbg8EcefBdbava8Ecdtfa3BdbarclfhramcufgmmbkavhrashminaPa8Aarydbg3cdtfydbg8Ec8F91cjjjj94Va8E7cQ4cx2fg8Ea8Eydbg8EcefBdbaXa8Ecdtfa3Bdbarclfhramcufgmmbkka8Jagfh8Ja8Kagfh8KaLcefgLci9hmbkaEaocetgrcuaocu9kEcbyd;0:G:cjbHjjjjbbgKBd:y9GaEclBd;S9Gdndnaoal9nmbaihralhminaKarydbcetfcFFi87ebarclfhramcufgmmbxdkkaKcFearz:rjjjb8Akcbh8EaEascbyd;0:G:cjbHjjjjbbg8ABd:C9GaOaHaHascdtfaHascitfa8AascbazaKaiawaDaqakz:hjjjbdndnalci6mba8Ahrashmina8EarRbbfh8EarcefhramcufgmmbkaE9cb83iwaE9cb83ibalawc9:fgrfcufar9UgrasaDfcufaD9Ugmaram0EhYcbhmcbhra8Ehaincbh3dnarTmba8AarfRbbceSh3kamaEaiaHydbcx2fgQydbaQclfydbaQcwfydbaKabaeadamawaqa3a3ce7a8EaY9nVaaamfaY6VGz:fjjjbfhmaHclfhHaaa8AarfRbb9Rhaasarcefgr9hmbkaEydxTmeabamcltfgraE8Piw83dwaraE8Pib83dbamcefhmxekaE9cb83iwaE9cb83ibcbhmkczhrinaEc:m;Gbfarfydbcbyd;4:G:cjbH:bjjjbbarc98fgrc989hmbkkaxc;W;Gbf8Kjjjjbamk:wKDQue99iue99iul9:euw99iu8Jjjjjbc;qb9RgP8Kjjjjbaxhsaxhzdndnavax0gHmbdnavTmbcbhOaehzavhAinawaDazydbcx2fgCcwfydbcetfgX8VebhQawaCclfydbcetfgL8VebhKawaCydbcetfgC8VebhYaXce87ebaLce87ebaCce87ebaOaKcs4aYcs4faQcs4ffhOazclfhzaAcufgAmbkaehzavhAinawaDazydbcx2fgCcwfydbcetfcFFi87ebawaCclfydbcetfcFFi87ebawaCydbcetfcFFi87ebazclfhzaAcufgAmbkcehzaqhsaOaq0mekalce86bbalcefcbavcufz:rjjjb8AxekaPaiBdxaPadBdwaPaeBdlavakaqci9Ug8Aaka8Aak6EaHEgK9RhEaxaK9Rh3aKcufh5aKceth8EaKcdtgCc98fh8FavcitgOaC9Rarfc98fhaascufhhavcufhgaraOfh8JJbbjZas:Y:vh8KcbazceakaxSEg8Lcdtg8M9Rh8NJFFuuhycuh8PcbhIcbh8RinaPclfa8RcdtfydbhQaPcb8Pd:y:G:cjbg8S83i9iaPcb8Pd:q:G:cjbgR83inaPcb8Pd1:G:cjbg8U83iUaPcb8Pdj:G:cjbg8V83i8WaPa8S83iyaPaR83iaaPa8U83iKaPa8V83izaQavcdtgYfh8WcbhXinabaQaXcdtgLfydbcK2fhAcbhzinaPc8WfazfgCaAazfgOIdbg8XaCIdbg8Ya8Xa8Y9DEUdbaCczfgCaOcxfIdbg8XaCIdbg8Ya8Xa8Y9EEUdbazclfgzcx9hmbkaba8WaXcu7cdtfydbcK2fhAcbhzaPIdUh8ZaPId9ih80aPId80h81aPId9ehBaPId8Wh83aPIdnhUinaPczfazfgCaAazfgOIdbg8XaCIdbg8Ya8Xa8Y9DEUdbaCczfgCaOcxfIdbg8XaCIdbg8Ya8Xa8Y9EEUdbazclfgzcx9hmbkaraLfgza80a8Z:tg8XaUa83:tg8YNa8YaBa81:tg8ZNa8Za8XNMMUdbazaYfaPIdyaPIdK:tg8XaPIdaaPIdz:tg8YNa8YaPId8KaPIdC:tg8ZNa8Za8XNMMUdbaXcefgXav9hmbkcbh85dnaHmbcbhAaQhza8JhCavhXinawaDazydbcx2fgOcwfydbcetfgL8Vebh8WawaOclfydbcetfg858Vebh86awaOydbcetfgO8Vebh87aLce87eba85ce87ebaOce87ebaCaAa86cs4a87cs4fa8Wcs4ffgABdbazclfhzaCclfhCaXcufgXmbkavhCinawaDaQydbcx2fgzcwfydbcetfcFFi87ebawazclfydbcetfcFFi87ebawazydbcetfcFFi87ebaQclfhQaCcufgCmbka8Jh85kdndndndndndndndndndndnava8E6mba8Eax9nmeavavaK9UgzaK29Raza320mda5aE9pmqa85Th87ceh8WaEhQxwka5ag9pmDa8Eax9nmixokavaK6mea5aE9pmwcehQaEhXa85Tmixlka5ag6mlxrka5ag9pmokcbhQaghXa85mekJFFuuh8XcbhLa5hzindnazcefgCaK6mbaQavaC9RgOaK6GmbarazcdtfIdbg8YaC:YNaravaz9RcdtfaYfc94fIdbg8ZaO:YNMg80a8X9Embdndna8KaOahf:YNg81:lJbbb9p9DTmba81:OhAxekcjjjj94hAka8ZasaA2aO9R:YNh8Zdndna8Kazasf:YNg81:lJbbb9p9DTmba81:OhOxekcjjjj94hOkamasaO2aC9R:Ya8YNa8ZMNa80Mg8Ya8Xa8Ya8X9DgOEh8XaCaLaOEhLkaza8LfgzaX6mbxlkkJFFuuh8XcbhLaEhCaahAa8FhOaKhzindnazaK6mbaQaCaK6GmbaraOfIdbg8Yaz:YNaAIdbg8ZaC:YNMg80a8X9Embdndna8Ka85aOfydbgYahf:YNg81:lJbbb9p9DTmba81:Oh8Wxekcjjjj94h8Wkamasa8W2aY9R:Yg81a8YNa8Za81NMNa80Mg8Ya8Xa8Ya8X9DgYEh8XazaLaYEhLkaCa8L9RhCaAa8NfhAaOa8MfhOaza8LfgzcufaX6mbxikka85Th87cbh8WaghQkJFFuuh8XcbhLaEhCaahAa8FhOaKhzindnazazaK9UgXaK29RaXa320mbdna8WTmbaCaCaK9UgXaK29RaXa320mekaraOfIdbg8Yaz:YNaAIdbg8ZaC:YNMg80a8X9EmbazhXaChYdna87mba85aOfydbgXhYkdndna8KaYahf:YNg81:lJbbb9p9DTmba81:Oh86xekcjjjj94h86ka8Zasa862aY9R:YNh8Zdndna8KaXahf:YNg81:lJbbb9p9DTmba81:OhYxekcjjjj94hYkamasaY2aX9R:Ya8YNa8ZMNa80Mg8Ya8Xa8Ya8X9DgXEh8XazaLaXEhLkaCa8L9RhCaAa8NfhAaOa8MfhOaza8LfgzcufaQ6mbkkaLTmba8Xay9DTmba8XhyaLhIa8Rh8Pka8Rcefg8Rci9hmbkdndnaoc8X9kmba8Pcb9omeka8Acufh85cbhYindndndnavaY9RaxaYaxfav0Eg8WTmbcbhAaeaYcdtfgzhCa8WhXinawaDaCydbcx2fgOcwfydbcetfgQ8VebhbawaOclfydbcetfgL8VebhrawaOydbcetfgO8VebhKaQce87ebaLce87ebaOce87ebaAarcs4aKcs4fabcs4ffhAaCclfhCaXcufgXmbka8WhOinawaDazydbcx2fgCcwfydbcetfcFFi87ebawaCclfydbcetfcFFi87ebawaCydbcetfcFFi87ebazclfhzaOcufgOmbkaAaq0mekalaYfgzce86bbazcefcba8Wcufz:rjjjb8AxekalaYfgzce86bbazcefcba85z:rjjjb8Aa8Ah8Wka8WaYfgYav9pmdxbkkaravcdtg8WfhLdnaITmbaPclfa8PcdtfydbhzaIhCinaLazydbfcb86bbazclfhzaCcufgCmbkkdnavaI9nmbaPclfa8PcdtfydbaIcdtfhzavaI9RhCinaLazydbfce86bbazclfhzaCcufgCmbkkcbhYindnaYa8PSmbcbhzaraPclfaYcdtfydbgKa8Wz:qjjjbhCavhXaIhOinaKaOazaLaCydbgQfRbbgAEcdtfaQBdbaCclfhCaOaAfhOazaA9RcefhzaXcufgXmbkkaYcefgYci9hmbkabaeadaialaIaocefgCarawaDaqakaxamz:hjjjbabaeaIcdtgzfadazfaiazfalaIfavaI9RaCarawaDaqakaxamz:hjjjbkaPc;qbf8Kjjjjbk:Seeru8Jjjjjbc:q;ab9Rgo8Kjjjjbaoc:q8WfcFecjzz:rjjjb8AcbhrdnadTmbaehwadhDinaoarcdtfawydbgqBdbaoc:q8WfaqcFiGcdtfgkydbhxakaqBdbawclfhwaraxaq9hfhraDcufgDmbkkabaeadaoaraiavz:jjjjbaoc:q;abf8Kjjjjbk;Sqloud99euD998Jjjjjbc:W;ab9Rgr8KjjjjbdndnadTmbaocd4hwcbhDcbhqindnavaeclfydbaw2cdtfgkIdbavaeydbaw2cdtfgxIdbgm:tgPavaecwfydbaw2cdtfgsIdlaxIdlgz:tgHNakIdlaz:tgOasIdbam:tgAN:tgCaCNaOasIdwaxIdwgX:tgQNakIdwaX:tgOaHN:tgHaHNaOaANaPaQN:tgPaPNMMgOJbbbb9Bmbarc8WfaDcltfgkaCaO:rgO:vgCUdwakaPaO:vgPUdlakaHaO:vgHUdbakaCaXNaHamNazaPNMM:mUdxaDcefhDkaecxfheaqcifgqad6mbkab9cb83dyab9cb83daab9cb83dKab9cb83dzab9cb83dwab9cb83dbaDTmearcbBd8Sar9cb83iKar9cb83izarczfavalaoarc8Sfcbcraiz:kjjjbarIdKhQarIdChLarIdzhKar9cb83iwar9cb83ibararc8WfaDczarc8Sfcbcicbz:kjjjbJbbbbhmdnarIdwgzazNarIdbgHaHNarIdlgXaXNMMgCJbbbb9BmbJbbjZaC:r:vhmkazamNhCaXamNhXaHamNhHJbbjZhmarc8WfheaDhvinaecwfIdbaCNaeIdbaHNaXaeclfIdbNMMgzamazam9DEhmaeczfheavcufgvmbkabaQUdwabaLUdlabaKUdbabarId3UdxdndnamJ;n;m;m899FmbJbbbbhzarc8WfheinaecxfIdbaQaecwfIdbgPNaKaeIdbgONaLaeclfIdbgANMMMaCaPNaHaONaXaANMM:vgPazaPaz9EEhzaeczfheaDcufgDmbkabaCUd8KabaXUdaabaHUd3abaQaCazN:tUdKabaLaXazN:tUdCabaKaHazN:tUdzabJbbjZamamN:t:rgmUdydndnaCJbbj:;aCJbbj:;9GEgzJbbjZazJbbjZ9FEJbb;:9cNJbbbZJbbb:;aCJbbbb9GEMgz:lJbbb9p9DTmbaz:Ohexekcjjjj94hekabae86b8UdndnaXJbbj:;aXJbbj:;9GEgzJbbjZazJbbjZ9FEJbb;:9cNJbbbZJbbb:;aXJbbbb9GEMgz:lJbbb9p9DTmbaz:Ohvxekcjjjj94hvkabav86bRdndnaHJbbj:;aHJbbj:;9GEgzJbbjZazJbbjZ9FEJbb;:9cNJbbbZJbbb:;aHJbbbb9GEMgz:lJbbb9p9DTmbaz:Ohwxekcjjjj94hwkabaw86b8SdndnaecKtcK91:YJbb;:9c:vaC:t:lavcKtcK91:YJbb;:9c:vaX:t:lawcKtcK91:YJbb;:9c:vaH:t:lamMMMJbb;:9cNJbbjZMgm:lJbbb9p9DTmbam:Ohexekcjjjj94hekaecFbaecFb9iEhexekabcjjj;8iBdycFbhekabae86b8Vxekab9cb83dyab9cb83daab9cb83dKab9cb83dzab9cb83dwab9cb83dbkarc:W;abf8Kjjjjbk;7woDuo99eue99euv998Jjjjjbcje9Rgw8Kjjjjbawc;abfcbaocdtgDz:rjjjb8Aawc;GbfcbaDz:rjjjb8AawcafhDawhqaohkinaqcFFF97BdbaDcFFF;7rBdbaqclfhqaDclfhDakcufgkmbkavcd4hxaicd4hmdnadTmbaocx2hPcbhsinashzdnarTmbarascdtfydbhzkaeazam2cdtfgDIdwhHaDIdlhOaDIdbhAalazax2cdtfIdbhCcbhDawcafhqawc;Gbfhvawhkawc;abfhiinaCaDc:O:G:cjbfIdbaHNaDc:G:G:cjbfIdbaANaDc:K:G:cjbfIdbaONMMgXMhQazhLdnaXaC:tgXaqIdbgK9DgYmbavydbhLkavaLBdbazhLdnaQakIdbg8A9EmbaiydbhLa8AhQkaiaLBdbakaQUdbaqaXaKaYEUdbaiclfhiakclfhkavclfhvaqclfhqaPaDcxfgD9hmbkascefgsad9hmbkkJbbbbhQcbhLawc;GbfhDawc;abfhqcbhkinalaqydbgvax2cdtfIdbalaDydbgiax2cdtfIdbaeavam2cdtfgvIdwaeaiam2cdtfgiIdw:tgCaCNavIdbaiIdb:tgCaCNavIdlaiIdl:tgCaCNMM:rMMgCaQaCaQ9EgvEhQakaLavEhLaqclfhqaDclfhDaoakcefgk9hmbkJbbbbhCdnaeawc;abfaLcdtgqfydbgkam2cdtfgDIdwaeawc;Gbfaqfydbgvam2cdtfgqIdwgH:tgXaXNaDIdbaqIdbgA:tg8Aa8ANaDIdlaqIdlgE:tgOaONMMgKJbbbb9ETmbaK:rgCalakax2cdtfIdbMalavax2cdtfIdb:taCaCM:vhCkaQJbbbZNhKaXaCNaHMhHaOaCNaEMhOa8AaCNaAMhAdnadTmbcbhqarhkinaqhDdnarTmbakydbhDkdnalaDax2cdtfIdbg3aeaDam2cdtfgDIdwaH:tgQaQNaDIdbaA:tgCaCNaDIdlaO:tgXaXNMMg5:rgEMg8EaK9ETmbJbbbbh8Adna5Jbbbb9ETmba8EaK:taEaEM:vh8Aka8AaQNaHMhHa8AaXNaOMhOa8AaCNaAMhAa3aKaEMMJbbbZNhKkakclfhkadaqcefgq9hmbkkabaKUdxabaHUdwabaOUdlabaAUdbawcjef8Kjjjjbk:reevu8Jjjjjbcj8W9Rgr8Kjjjjbaici2hwcbhDdnaiTmbarhiawhqinaiaeadRbbgkcdtfydbBdbaDakcefgkaDak0EhDaiclfhiadcefhdaqcufgqmbkkabarawaeaDalaoz:jjjjbarcj8Wf8Kjjjjbk:Eeeeu8Jjjjjbca9Rgo8Kjjjjbab9cb83dyab9cb83daab9cb83dKab9cb83dzab9cb83dwab9cb83dbdnadTmbaocbBd3ao9cb83iwao9cb83ibaoaeadaialaoc3falEavcbalEcrcbz:kjjjbabao8Pib83dbabao8Piw83dwkaocaf8Kjjjjbk::meQu8Jjjjjbcjz9Rgv8KjjjjbcbhoavcjPfcbaez:rjjjb8Aavcjxfcbaez:rjjjb8AdnaiTmbadhoaihrinavcjxfaoRbbfgwawRbbcef86bbavcjxfaocefRbbfgwawRbbcef86bbavcjxfaocdfRbbfgwawRbbcef86bbaocifhoarcufgrmbkcbhDcjehoadhqcehkindndnalTmbcbhxcuhmaqhrakhwcuhPinawcufamaoavcjPfarcefRbbgsfRbb9RcFeGgzci6aoavcjPfarRbbgHfRbb9RcFeGgOci6faoavcjPfarcdfRbbgAfRbb9RcFeGgCci6fgXcOtaOcFr7azaCf9RcwtVavcjxfaAfRbbgzavcjxfaHfRbbgHavcjxfasfRbbgsaHas6Egsazas6EcFe7VgsaP9kgzEhmaXcd6gHaxcefgOal9iVce9hmdasaPazEhPaxaOaHEhxarcifhrawai6hsawcefhwasmbxdkkcuhmaqhrakhwcuhxinawcufamaoavcjPfarcefRbbfRbb9RcFeGci6aoavcjPfarRbbfRbb9RcFeGci6faoavcjPfarcdfRbbfRbb9RcFeGci6fgPax9kgsEhmaPce0meaPaxasEhxarcifhrawai6hPawcefhwaPmbkkadamci2fgrcdfRbbhwarcefRbbhxarRbbhPadaDci2fgrcifaramaD9Rci2zNjjjb8AaPavcjPffaocefgo86bbaPavcjxffgmamRbbcuf86bbaxavcjPffao86bbaxavcjxffgmamRbbcuf86bbarcdfaw86bbarcefax86bbaraP86bbawavcjPffao86bbawavcjxffgrarRbbcuf86bbaqcifhqakcefhkaDcefgDai9hmbkcbhzdnalcb9mmbcbhsavcjPfcbaez:rjjjb8Aadcvfhlinadasci2fgxcefgDRbbhoaxcdfgqRbbhrdndnavcjPfaxRbbgmfRbbmbavcjPfarfRbbhwdndndnavcjPfaofRbbTmbawcFeGTmexikawcFeGmdascefgAai9pmdasc980mdascifhQcbhLarcFeGhCamcFeGhXalhwcbhKcbhYinawcufRbbhPawRbbhOcehkdndnawc9:fRbbgHao9hmbaPcFeGamSmekdnaPcFeGao9hmbaOcFeGamSmekaHamSaOcFeGaoSGhkkceh8AaYceGhYdndnaHar9hmbaPcFeGaoSmekdnaPcFeGar9hmbaOcFeGaoSmekaHaoSaOcFeGarSGh8AkakaYVhYaLaHcFeGgHaXSaPcFeGgPaCSGaPaXSaOcFeGgPaCSGVaHaCSaPaXSGVVhLa8AaKceGVhKdnaAcefgPai9pmbawcifhwaAaQ6hHaPhAaHmekkaYTmeaKmekarhwaohPaohHarhOamhrxdkdnaYTaLVceGTmbaYaKTVaLVceGmekamhwarhParhHamhOaohrxekaohwamhPamhHaohOkavcjPfarfce86bbavcjPfawfce86bbaxaH86bbaqar86bbaDaO86bbavcjPfaPfce86bbalcifhlascefgsai9hmbkkavcFeaecetz:rjjjbhwaici2hrindnawadRbbgmcetfgx8Uebgocu9kmbaxaz87ebawcjlfazcdtfabamcdtfydbBdbazhoazcefhzkadao86bbadcefhdarcufgrmbkazcdthokabavcjlfaoz:qjjjb8Aavcjzf8KjjjjbkObabaiaeadcbz:njjjbk9teiucbcbyd;8:G:cjbgeabcifc98GfgbBd;8:G:cjbdndnabZbcztgd9nmbcuhiabad9RcFFifcz4nbcuSmekaehikaik;LeeeudndnaeabVciGTmbabhixekdndnadcz9pmbabhixekabhiinaiaeydbBdbaiclfaeclfydbBdbaicwfaecwfydbBdbaicxfaecxfydbBdbaeczfheaiczfhiadc9Wfgdcs0mbkkadcl6mbinaiaeydbBdbaeclfheaiclfhiadc98fgdci0mbkkdnadTmbinaiaeRbb86bbaicefhiaecefheadcufgdmbkkabk;aeedudndnabciGTmbabhixekaecFeGc:b:c:ew2hldndnadcz9pmbabhixekabhiinaialBdbaicxfalBdbaicwfalBdbaiclfalBdbaiczfhiadc9Wfgdcs0mbkkadcl6mbinaialBdbaiclfhiadc98fgdci0mbkkdnadTmbinaiae86bbaicefhiadcufgdmbkkabk9teiucbcbyd;8:G:cjbgeabcrfc94GfgbBd;8:G:cjbdndnabZbcztgd9nmbcuhiabad9RcFFifcz4nbcuSmekaehikaikTeeucbabcbyd;8:G:cjbge9Rcifc98GaefgbBd;8:G:cjbdnabZbcztge9nmbabae9RcFFifcz4nb8Akk:3qeludndnadch6mbadTmeabaead;8qbbabskabaeSmbdnaeadabfgi9Rcbadcet9R0mbadTmeabaead;8qbbabskaeab7ciGhldndndnabae9pmbdnalTmbadhvabhixikdnabciGmbadhvabhixdkadTmiabaeRbb86bbadcufhvdnabcefgiciGmbaecefhexdkavTmiabaeRbe86beadc9:fhvdnabcdfgiciGmbaecdfhexdkavTmiabaeRbd86bdadc99fhvdnabcifgiciGmbaecifhexdkavTmiabaeRbi86biabclfhiaeclfheadc98fhvxekdnalmbdnaiciGTmbadTmlabadcufgifglaeaifRbb86bbdnalciGmbaihdxekaiTmlabadc9:fgifglaeaifRbb86bbdnalciGmbaihdxekaiTmlabadc99fgifglaeaifRbb86bbdnalciGmbaihdxekaiTmlabadc98fgdfaeadfRbb86bbkadcl6mbdnadc98fgocxGcxSmbaocd4cefciGhiaec98fhlabc98fhvinavadfaladfydbBdbadc98fhdaicufgimbkkaocx6mbaec9Wfhvabc9WfhoinaoadfgicxfavadfglcxfydbBdbaicwfalcwfydbBdbaiclfalclfydbBdbaialydbBdbadc9Wfgdci0mbkkadTmdadhidnadciGglTmbaecufhvabcufhoadhiinaoaifavaifRbb86bbaicufhialcufglmbkkadcl6mdaec98fhlabc98fhvinavaifgecifalaifgdcifRbb86bbaecdfadcdfRbb86bbaecefadcefRbb86bbaeadRbb86bbaic98fgimbxikkavcl6mbdnavc98fglc3Gc3Smbavalcd4cefcrGgdcdt9RhvinaiaeydbBdbaeclfheaiclfhiadcufgdmbkkalc36mbinaiaeydbBdbaiclfaeclfydbBdbaicwfaecwfydbBdbaicxfaecxfydbBdbaiczfaeczfydbBdbaicCfaecCfydbBdbaicKfaecKfydbBdbaic3faec3fydbBdbaecafheaicafhiavc9Gfgvci0mbkkavTmbdndnavcrGgdmbavhlxekavc94GhlinaiaeRbb86bbaicefhiaecefheadcufgdmbkkavcw6mbinaiaeRbb86bbaicefaecefRbb86bbaicdfaecdfRbb86bbaicifaecifRbb86bbaiclfaeclfRbb86bbaicvfaecvfRbb86bbaicofaecofRbb86bbaicrfaecrfRbb86bbaicwfhiaecwfhealc94fglmbkkabkk:pedbcj:GdktFFuuFFuuFFuubbbbFFuFFFuFFFuFbbbbbbjZbbbbbbbbbbbbbbjZbbbbbbbbbbbbbbjZ86;nAZ86;nAZ86;nAZ86;nA:;86;nAZ86;nAZ86;nAZ86;nA:;86;nAZ86;nAZ86;nAZ86;nA:;bc;0:Gdkxebbbdbbbj:qbb",e=new Uint8Array([32,0,65,2,1,106,34,33,3,128,11,4,13,64,6,253,10,7,15,116,127,5,8,12,40,16,19,54,20,9,27,255,113,17,42,67,24,23,146,148,18,14,22,45,70,69,56,114,101,21,25,63,75,136,108,28,118,29,73,115]);if(typeof WebAssembly!="object")return{supported:!1};var t,a=WebAssembly.instantiate(i(n),{}).then(function(g){t=g.instance,t.exports.__wasm_call_ctors()});function i(g){for(var m=new Uint8Array(g.length),u=0;u<g.length;++u){var y=g.charCodeAt(u);m[u]=y>96?y-97:y>64?y-39:y+4}for(var x=0,u=0;u<g.length;++u)m[x++]=m[u]<60?e[m[u]]:(m[u]-60)*64+m[++u];return m.buffer.slice(0,x)}function r(g){if(!g)throw new Error("Assertion failed")}function s(g){return new Uint8Array(g.buffer,g.byteOffset,g.byteLength)}var o=48,c=16;function l(g,m){var u=g.meshlets[m*4+0],y=g.meshlets[m*4+1],x=g.meshlets[m*4+2],v=g.meshlets[m*4+3];return{vertices:g.vertices.subarray(u,u+x),triangles:g.triangles.subarray(y,y+v*3)}}function h(g,m,u,y,x,v,E,_,A,k){var w=t.exports.sbrk,M=t.exports.meshopt_buildMeshletsBound(m.length,v,E),R=w(M*c),U=w(m.length*4),P=w(m.length),D=w(m.byteLength),V=w(u.byteLength),B=new Uint8Array(t.exports.memory.buffer);B.set(s(m),D),B.set(s(u),V);var G=g(R,U,P,D,m.length,V,y,x,v,E,_,A,k);B=new Uint8Array(t.exports.memory.buffer);for(var z=B.subarray(R,R+G*c),Y=new Uint32Array(z.buffer,z.byteOffset,z.byteLength/4).slice(),te=0;te<G;++te){var ie=Y[te*4+0],pe=Y[te*4+1],y=Y[te*4+2],Te=Y[te*4+3];t.exports.meshopt_optimizeMeshlet(U+ie*4,P+pe,Te,y)}var W=G?Y[(G-1)*4+0]+Y[(G-1)*4+2]:0,J=G?Y[(G-1)*4+1]+Y[(G-1)*4+3]*3:0,se={meshlets:Y,vertices:new Uint32Array(B.buffer,U,W).slice(),triangles:new Uint8Array(B.buffer,P,J).slice(),meshletCount:G};return w(R-w(0)),se}function d(g){var m=new Float32Array(t.exports.memory.buffer,g,o/4);return{centerX:m[0],centerY:m[1],centerZ:m[2],radius:m[3],coneApexX:m[4],coneApexY:m[5],coneApexZ:m[6],coneAxisX:m[7],coneAxisY:m[8],coneAxisZ:m[9],coneCutoff:m[10]}}function f(g,m,u,y){var x=t.exports.sbrk,v=[],E=x(m.byteLength),_=x(g.vertices.byteLength),A=x(g.triangles.byteLength),k=x(o),w=new Uint8Array(t.exports.memory.buffer);w.set(s(m),E),w.set(s(g.vertices),_),w.set(s(g.triangles),A);for(var M=0;M<g.meshletCount;++M){var R=g.meshlets[M*4+0],U=g.meshlets[M*4+1],P=g.meshlets[M*4+3];t.exports.meshopt_computeMeshletBounds(k,_+R*4,A+U,P,E,u,y),v.push(d(k))}return x(E-x(0)),v}function b(g,m,u,y){var x=t.exports.sbrk,v=x(o),E=x(g.byteLength),_=x(m.byteLength),A=new Uint8Array(t.exports.memory.buffer);A.set(s(g),E),A.set(s(m),_),t.exports.meshopt_computeClusterBounds(v,E,g.length,_,u,y);var k=d(v);return x(v-x(0)),k}function p(g,m,u,y,x){var v=t.exports.sbrk,E=v(o),_=v(g.byteLength),A=y?v(y.byteLength):0,k=new Uint8Array(t.exports.memory.buffer);k.set(s(g),_),y&&k.set(s(y),A),t.exports.meshopt_computeSphereBounds(E,_,m,u,A,y?x:0);var w=d(E);return v(E-v(0)),w}return{ready:a,supported:!0,buildMeshlets:function(g,m,u,y,x,v){r(g.length%3==0),r(m instanceof Float32Array),r(m.length%u==0),r(u>=3),r(y>=3&&y<=256),r(x>=1&&x<=512),v=v||0;var E=g.BYTES_PER_ELEMENT==4?g:new Uint32Array(g);return h(t.exports.meshopt_buildMeshletsFlex,E,m,m.length/u,u*4,y,x,x,v,0)},buildMeshletsFlex:function(g,m,u,y,x,v,E,_){r(g.length%3==0),r(m instanceof Float32Array),r(m.length%u==0),r(u>=3),r(y>=3&&y<=256),r(x>=1&&v<=512),r(x<=v),E=E||0,_=_||0;var A=g.BYTES_PER_ELEMENT==4?g:new Uint32Array(g);return h(t.exports.meshopt_buildMeshletsFlex,A,m,m.length/u,u*4,y,x,v,E,_)},buildMeshletsSpatial:function(g,m,u,y,x,v,E){r(g.length%3==0),r(m instanceof Float32Array),r(m.length%u==0),r(u>=3),r(y>=3&&y<=256),r(x>=1&&v<=512),r(x<=v),E=E||0;var _=g.BYTES_PER_ELEMENT==4?g:new Uint32Array(g);return h(t.exports.meshopt_buildMeshletsSpatial,_,m,m.length/u,u*4,y,x,v,E)},extractMeshlet:function(g,m){return r(m>=0&&m<g.meshletCount),l(g,m)},computeClusterBounds:function(g,m,u){r(g.length%3==0),r(g.length/3<=512),r(m instanceof Float32Array),r(m.length%u==0),r(u>=3);var y=g.BYTES_PER_ELEMENT==4?g:new Uint32Array(g);return b(y,m,m.length/u,u*4)},computeMeshletBounds:function(g,m,u){return r(m instanceof Float32Array),r(m.length%u==0),r(u>=3),f(g,m,m.length/u,u*4)},computeSphereBounds:function(g,m,u,y){return r(g instanceof Float32Array),r(g.length%m==0),r(m>=3),r(!u||u instanceof Float32Array),r(!u||u.length%y==0),r(!u||y>=1),r(!u||g.length/m==u.length/y),y=y||0,p(g,g.length/m,m*4,u,y*4)}}})();(function(){var n="b9H79Tebbbe9vx9Geueu9Geub9Gbb9Gkuuuuuuuuuuub9Gouuuuuub9Gwuuuuuu9999b9Giuuueu9Ge98e999Gvuuuuueu9Gd99ueu9Ge99e999Gd98ue98isPdilvboberrwDqklve9Weiiviebeoweuecj:Gdkr9Avo9TW9T9VV95dbH9F9F939H79T9F9J9H229F9Jt9VV7bbK9TW79O9V9Wt9F9NW9UWV9HtW9u9H9U9NW9Ut7beL9TW79O9V9Wt9F9NW9UWV9HtW9o9VV9T9H27bil79IV9RblDwebcekdorq;X9PPdbk;e8EvHuw99euv99wu8Jjjjjbc;Wb9Rgk8Kjjjjbakcxfcbc;Kbz:fjjjb8AakcualcdtalcFFFFi0Ecbyd:W:2:cjbHjjjjbbgxBdxakceBd2adci9Uhmalcd4alfhPcehsinasgzcethsazaP6mbkakcuazcdtgsazcFFFFi0Ecbyd:W:2:cjbHjjjjbbgPBdzakcdBd2aPcFeasz:fjjjbhHaDcd4hOarcd4hAavcd4hCdnalTmbazcufhrcbhvindndnaHcbaiavaC2cdtfgzydlgDaDcjjjj94SEgPcH4cbaoavaA2cdtfgsydlgXcs4aXcjjjj94SE7aP7c:F:b:DD2cbazydbgQaQcjjjj94SEgPcH4cbasydbgLcs4aLcjjjj94SE7aP7c;D;O:B8J27cbazydwgKaKcjjjj94SEgzcH4cbasydwgYcs4aYcjjjj94SE7az7c:3F;N8N27awavaO2cdtfgzydlg8AazydbgE7cFFFFrGgzcm4az7c:fjjK27arGgPcdtfgzydbgscuSmba8A::h3aE::h5aY::h8EaX::h8FaL::haaK::hhaD::hgaQ::h8JcehDinaDhzdnaiasaC2cdtfgDIdba8J9CmbaDIdlag9CmbaDIdwah9CmbaoasaA2cdtfgDIdbaa9CmbaDIdla8F9CmbaDIdwa8E9CmbawasaO2cdtfgDIdba59CmbaDIdla39BmikazcefhDaHaPazfarGgPcdtfgzydbgscu9hmbkkazavBdbavhskaxavcdtfasBdbavcefgval9hmbkkcbhPaHcbyd:0:2:cjbH:bjjjbbakceBd2ak9cb83ibakaeadaxalakcxfz:cjjjbcuamcltadcFFFFd0Ecbyd:W:2:cjbHjjjjbbh8Kakcxfakyd2gKcdtfa8KBdbakaKcefgYBd2dnadci6mbaehsa8KhzamhvindndnaeTmbascwfydbhDasclfydbhHasydbhrxekaPcdfhDaPcefhHaPhrkJbbbbh8JJbbbbJbbbbJbbbbJbbbbJbbjZJbbj:;awaHaO2cdtfgXIdbawaraO2cdtfgQIdbga:tawaDaO2cdtfgLIdlaQIdlgh:tggNaXIdlah:tghaLIdbaa:tN:tgaJbbbb9EEaaJbbbb9BEg5aiaraC2cdtfgrIdwgaaiaHaC2cdtfgHIdwg39BEa5arIdlg8FaHIdlg8L9BEa5arIdbg8EaHIdbg8M9BEg5aaaiaDaC2cdtfgDIdwg8N9BEa5a8FaDIdlgy9BEa5a8EaDIdbg8P9BEg5a3a8N9BEa5a8Lay9BEa5a8Ma8P9BEh5dnaga3aa:tNaha8Naa:tN:tgaaaNaga8Ma8E:tNaha8Pa8E:tN:tg8Ea8ENaga8La8F:tNahaya8F:tN:tggagNMMghJbbbb9Bmba5ah:r:vh8Jkazcxfa5Udbazcwfaaa8JNUdbazclfaga8JNUdbaza8Ea8JNUdbascxfhsazczfhzaPcifhPavcufgvmbkkcbhzakcxfaYcdtfcuadcdtadcFFFFi0Ecbyd:W:2:cjbHjjjjbbgDBdbakaKcdfgPBd2dnadTmbaDhsinasazBdbasclfhsadazcefgz9hmbkkakcxfaPcdtfcuamcdtadcFFFF970Ecbyd:W:2:cjbHjjjjbbgvBdbakaKcifgzBd2akcxfazcdtfamcbyd:W:2:cjbHjjjjbbgYBdbakaKclfBd2dnadci6mba8KcxfhsavhPcbhzinaPazBdbaYazfcdcbasIdbg8JJbbbb9DEa8JJbbbb9EV86bbaPclfhPasczfhsamazcefgz9hmbkkdnalTmbcbhIakydlh8Rakydbh8SinaIcdthzdna8SaIcefgIcdtfydbgsa8SazfydbgzSmbasaz9RhQa8RazcdtfhLcbhRinaLaRcdtfg8Uydbgzcd4g8Vci2g8WazciGcdtgsyd:e:G:cjbfhza8Wasydj:G:cjbfhsdnaeTmbaeazcdtfydbhzaeascdtfydbhskdnaRcefgRaQ9pmbaxazcdtfydbhKaxascdtfydbhEaYa8Vfh8Aava8Vcdtfh8XaRhwinaLawcdtfgXydbgzcd4gsci2gOazciGcdtgzyd:e:G:cjbfhPaOazydj:G:cjbfhzdnaeTmbaeaPcdtfydbhPaeazcdtfydbhzkdndnaxazcdtfydbaKSmbaxaPcdtfydbaE9hmekaYasfRbbgza8ARbbgPVciSmbdnazaPGmba8VhPdna8Va8XydbgzSmba8XhHinaHavazgPcdtfgrydbgzBdbarhHaPaz9hmbkkdnasavascdtfgHydbgzSmbinaHavazgscdtfgrydbgzBdbarhHasaz9hmbkkaPasSmbaYasfgHRbbaYaPfgzRbbVciSmeavascdtfaPBdbazazRbbaHRbbV86bbkdna8UydbciGa8WfgsaDascdtfgPydbgzSmbinaPaDazgscdtfgHydbgzBdbaHhPasaz9hmbkkdnaXydbciGaOfgPaDaPcdtfgHydbgzSmbinaHaDazgPcdtfgrydbgzBdbarhHaPaz9hmbkkasaPSmbaDaPcdtfasBdbkawcefgwaQ9hmbkkaRaQ9hmbkkaIal9hmbkkdnadTmbcbhrinarhsdnaraDarcdtfgwydbgzSmbawhPinaPaDazgscdtfgHydbgzBdbaHhPasaz9hmbkkawasBdbarcefgrad9hmbkcbh8Vabcbadcltz:fjjjbhQdnadci6mbaqceGhKaDhLaeh8Acbh8Windna8Ka8WcltfgPIdxJbbbb9Bmbaea8Wci2gEcdtfhXcbhsa8VhwinaQaLasfydbcltfhzdndnaeTmba8AasfydbhHaXasc:e:G:cjbfydbcdtfydbhOaXascj:G:cjbfydbcdtfydbhxxekasc:e:G:cjbfydbaEfhOascj:G:cjbfydbaEfhxawhHkazaPIdbghaoaHaA2cdtfgrIdbg8JaPIdwg8EarIdwggNaha8JNaPIdlg5arIdlghNMMgaN:tg8FJbbbbJbbjZa8EagaaN:tg8Ea8ENa8Fa8FNa5ahaaN:tgaaaNMMg8F:r:va8FJbbbb9BEJ;As6nJbbjZaiaxaC2cdtfgrIdwaiaHaC2cdtfgHIdwg3:tg8Faga8FagNarIdbaHIdbg8L:tg8Ma8JNaharIdlaHIdlg8N:tgyNMMg8FN:tg5aiaOaC2cdtfgHIdwa3:tg3aga3agNaHIdba8L:tg8Pa8JNahaHIdla8N:tg8NNMMg3N:tggNa8Ma8Ja8FN:tg8La8Pa8Ja3N:tg8JNayaha8FN:tg8Fa8Naha3N:tghNMMJbbbbJbbjZa5a5Na8La8LNa8Fa8FNMMagagNa8Ja8JNahahNMMNg8J:rgg:va8JJbbbb9BENgh:lg8Ja8JJbbjZ9EEg8Ja8JJ7;A9s89NJ:L9t9s::MNJ;ob;jZMJbbjZa8J:t:rNg8J:ta8JahJbbbb9DENg8Jaga8JNaKEg8JNazIdbMUdbazaaa8JNazIdlMUdlaza8Ea8JNazIdwMUdwawcefhwasclfgscx9hmbkkaLcxfhLa8Acxfh8Aa8Vcifh8Va8Wcefg8Wam9hmbkcbhrinarhsdnaravarcdtfgPydbgzSmbinaPavazgscdtfgHydbgzBdbaHhPasaz9hmbkkaQarc8W2fgzc3fJbbjZJbbj:;aYasfRbbceGEg8JUdbazc8Sfa8JUdbaza8JUdxarcefgram9hmbkkaqcdGhvcbhsaDhPaQhzindnasaPydb9hmbdndnazcwfgHIdbg8Ja8JNazIdbggagNazclfgrIdbghahNMMgaJbbbb9BmbaHa8JJbbjZaa:r:vgaNUdbarahaaNUdbazagaaNg8JUdbxekaHa8JJbbbbNUdbarahJbbbbNUdbazagJbbbbNg8JUdba8JJbbjZavEh8Jkaza8JUdbkaPclfhPazczfhzadascefgs9hmbkcbhzaQhsindnazaDydbgPSmbasaQaPcltfgPydwBdwasaP8Pdb83dbkaDclfhDasczfhsadazcefgz9hmbkkdnakyd2gsTmbascdtakcxffc98fhzinazydbcbyd:0:2:cjbH:bjjjbbazc98fhzascufgsmbkkakc;Wbf8Kjjjjbk;:levucualcefgocdtaocFFFFi0Ecbyd:W:2:cjbHjjjjbbhoavavyd9GgrcdtfaoBdbavarcefBd9GabaoBdbcuadcdtadcFFFFi0Ecbyd:W:2:cjbHjjjjbbhoavavyd9GgrcdtfaoBdbavarcefBd9GabaoBdlabydbclfcbalcdtz:fjjjbhoadci9UhwdnadTmbdnaeTmbaehvadhrinaoaiavydbcdtfydbcdtfgDaDydbcefBdbavclfhvarcufgrmbxdkkadhraihvinaoavydbcdtfgDaDydbcefBdbavclfhvarcufgrmbkkdnalTmbcbhraohvinavydbhDavarBdbavclfhvaDarfhralcufglmbkkdnadci6mbabydlhrcbhlcdhvindndnaeTmbaiaealfgqydbcdtfhDaiaqcwfydbcdtfhdaiaqclfydbcdtfhqxekaialfgDcwfhdaDclfhqkadydbhdaqydbhqaoaDydbcdtfgDaDydbgDcefBdbaraDcdtfavc9:fBdbaoaqcdtfgDaDydbgDcefBdbaraDcdtfavcufBdbaoadcdtfgDaDydbgDcefBdbaraDcdtfavBdbalcxfhlavclfhvawcufgwmbkkabydbcbBdbk:SEvxui99duv99xu8Jjjjjbc;Wb9Rgw8Kjjjjbawcxfcbc;Kbz:fjjjb8AawcualcdtalcFFFFi0Ecbyd:W:2:cjbHjjjjbbgDBdxawceBd2adci9Uhqalcd4alfhkaoz:mjjjbhocehxinaxgmcethxamak6mbkawcuamcdtgxamcFFFFi0Ecbyd:W:2:cjbHjjjjbbgkBdzawcdBd2akcFeaxz:fjjjbhPavcd4hsdnalTmbamcufhzcbhHindndnaPcbaiaHas2cdtfgmydlgvavcjjjj94SEgxcH4ax7c:F:b:DD2cbamydbgOaOcjjjj94SEgxcH4ax7c;D;O:B8J27cbamydwgAaAcjjjj94SEgmcH4am7c:3F;N8N27azGgkcdtfgmydbgxcuSmbaA::hCav::hXaO::hQcehvinavhmdnaiaxas2cdtfgvIdbaQ9CmbavIdlaX9CmbavIdwaC9BmikamcefhvaPakamfazGgkcdtfgmydbgxcu9hmbkkamaHBdbaHhxkaDaHcdtfaxBdbaHcefgHal9hmbkkcbhkaPcbyd:0:2:cjbH:bjjjbbawceBd2aw9cb83ibawaeadaDalawcxfz:cjjjbcuaqcltadcFFFFd0Ecbyd:W:2:cjbHjjjjbbhLawcxfawyd2gKcdtfaLBdbawaKcefgOBd2dnadci6mbaehxaLhmaqhHindndnaeTmbaxcwfydbhzaxclfydbhvaxydbhPxekakcdfhzakcefhvakhPkJbbbbhQdnaiavas2cdtfgvIdbaiaPas2cdtfgPIdbgX:tgYaiazas2cdtfgzIdlaPIdlgC:tg8ANavIdlaC:tgCazIdbaX:tgEN:tgXaXNaCazIdwaPIdwg3:tg5NavIdwa3:tg3a8AN:tgCaCNa3aENaYa5N:tgYaYNMMg8AJbbbb9BmbJbbjZa8A:r:vhQkamcxfa8AJbbbb9CBdbamcwfaXaQNUdbamclfaYaQNUdbamaCaQNUdbaxcxfhxamczfhmakcifhkaHcufgHmbkkcbhmawcxfaOcdtfcuadcdtg8EadcFFFFi0Ecbyd:W:2:cjbHjjjjbbgvBdbawaKcdfg8FBd2dnadTmbavhxinaxamBdbaxclfhxadamcefgm9hmbkkdnalTmbcbhaawydlhhawydbhginaacdthmdnagaacefgacdtfydbgxagamfydbgmSmbaxam9RhAahamcdtfh8Jcbh8Kina8Ja8Kcdtfg8Lydbgmcd4gkci2g8MamciGcdtgxyd:e:G:cjbfhma8Maxydj:G:cjbfhxdnaeTmbaeamcdtfydbhmaeaxcdtfydbhxkdna8Kcefg8KaA9pmbaLakcltfhOaDamcdtfydbh8NaDaxcdtfydbhya8KhHina8JaHcdtfg8Pydbgmcd4gkci2gzamciGgPcdtgmyd:e:G:cjbfhxazamydj:G:cjbfhmdnaeTmbaeaxcdtfydbhxaeamcdtfydbhmkdndnaDamcdtfydba8NSmbaDaxcdtfydbay9hmekaOIdwaLakcltfgmIdwNaOIdbamIdbNaOIdlamIdlNMMao9ETmbaOydxamydx9hmbdna8LydbciGa8MfgxavaxcdtfgkydbgmSmbinakavamgxcdtfgPydbgmBdbaPhkaxam9hmbka8PydbciGhPkdnaPazfgkavakcdtfgPydbgmSmbinaPavamgkcdtfgzydbgmBdbazhPakam9hmbkkaxakSmbavakcdtfaxBdbkaHcefgHaA9hmbkka8KaA9hmbkkaaal9hmbkkdndndnadTmbcbhzinazhxdnazavazcdtfgHydbgmSmbaHhkinakavamgxcdtfgPydbgmBdbaPhkaxam9hmbkkaHaxBdbazcefgzad9hmbkcbh8Mabcbadcx2z:fjjjbh8Padcd9nmeavhAaeh8NcbhyinaLaycltfhkaeayci2g8JcdtfhDcbhxa8MhHina8PaAaxfydbcx2fhmdndnaeTmba8NaxfydbhzaDaxc:e:G:cjbfydbcdtfydbhOaDaxcj:G:cjbfydbcdtfydbhPxekaxc:e:G:cjbfydba8JfhOaxcj:G:cjbfydba8JfhPaHhzkamakIdbaiaPas2cdtfgPIdwaiazas2cdtfgzIdwgC:tgoaoNaPIdbazIdbgY:tgQaQNaPIdlazIdlg8A:tgXaXNMMaiaOas2cdtfgPIdwaC:tgCaCNaPIdbaY:tgYaYNaPIdla8A:tg8Aa8ANMMNgE:rg3J;As6nJbbjZaoaCNaQaYNaXa8ANMMJbbbbJbbjZa3:vaEJbbbb9BENgQ:lgoaoJbbjZ9EEgoaoJ7;A9s89NJ:L9t9s::MNJ;ob;jZMJbbjZao:t:rNgo:taoaQJbbbb9DENgoNamIdbMUdbamakIdlaoNamIdlMUdlamakIdwaoNamIdwMUdwaHcefhHaxclfgxcx9hmbkaAcxfhAa8Ncxfh8Na8Mcifh8MaycefgyaqSmdxbkkabcbadcx2z:fjjjb8Axekcbhxavhka8Phmindnaxakydb9hmbJbbbbhodnamcwfgPIdbgQaQNamIdbgXaXNamclfgzIdbgCaCNMMgYJbbbb9BmbJbbjZaY:r:vhokaPaQaoNUdbazaCaoNUdbamaXaoNUdbkakclfhkamcxfhmadaxcefgx9hmbkkdnarJbbbb9ETmbawcxfa8Fcdtfcuadcltg8Pa8EcFFFFi0Ecbyd:W:2:cjbHjjjjbbg8JBdbdndnar:ngo:lJbbb9p9DTmbao:Ohmxekcjjjj94hmkaKcifh8Famce9imbamcqamcq9iEh8Nadci6hLcbhAina8Jcba8Pz:fjjjbhPdnaLmbcbhDavhOinavaDcx2fhecbhxinabaOaxfydbgzcx2fgmIdwhoabaeaxcj:G:cjbfydbcdtfydbgHcx2fgkIdwhQamIdbhXakIdbhCamIdlhYakIdlh8AaPazcltfgmamIdxJbbjZMUdxamamIdbaCaX:taoaQNaXaCNaYa8ANMMgXaXNJbbbbaXJbbbb9EEgXNgCMUdbamamIdla8AaY:taXNgYMUdlamaQao:taXNgoamIdwMUdwaPaHcltfgmamIdxJbbjZMUdxamamIdbaC:tUdbamamIdlaY:tUdlamamIdwao:tUdwaxclfgxcx9hmbkaOcxfhOaDcefgDaq9hmbkkdnadTmbaraA:Z:tgoJbbjZaoJbbjZ9DEJbbbZNh8AcbhxavhkabhzaPhmindnaxakydb9hmbamcxfIdbgQJbbbb9ETmbJbbbbhodnamcwfIdba8AaQ:vgQNazcwfgPIdbMgXaXNamIdbaQNazIdbMgCaCNamclfIdbaQNazclfgHIdbMgQaQNMMgYJbbbb9BmbJbbjZaY:r:vhokaPaXaoNUdbaHaQaoNUdbazaCaoNUdbkakclfhkazcxfhzamczfhmadaxcefgx9hmbkkaAcefgAa8N9hmbkkdnadTmbcbhmabhxindnamavydbgkSmbaxabakcx2fgkydwBdwaxak8Pdb83dbkavclfhvaxcxfhxadamcefgm9hmbkkdna8FTmba8Fcdtawcxffc98fhminamydbcbyd:0:2:cjbH:bjjjbbamc98fhma8Fcufg8Fmbkkawc;Wbf8Kjjjjbk9teiucbcbyd:4:2:cjbgeabcifc98GfgbBd:4:2:cjbdndnabZbcztgd9nmbcuhiabad9RcFFifcz4nbcuSmekaehikaik;aeedudndnabciGTmbabhixekaecFeGc:b:c:ew2hldndnadcz9pmbabhixekabhiinaialBdbaicxfalBdbaicwfalBdbaiclfalBdbaiczfhiadc9Wfgdcs0mbkkadcl6mbinaialBdbaiclfhiadc98fgdci0mbkkdnadTmbinaiae86bbaicefhiadcufgdmbkkabk9teiucbcbyd:4:2:cjbgeabcrfc94GfgbBd:4:2:cjbdndnabZbcztgd9nmbcuhiabad9RcFFifcz4nbcuSmekaehikaikTeeucbabcbyd:4:2:cjbge9Rcifc98GaefgbBd:4:2:cjbdnabZbcztge9nmbabae9RcFFifcz4nb8Akk9pee98abab:Igbabab:Ige:Iab9e9P9q;U;G9c:t;58::I9e8N8Es;O:h;a9w:;:G:Iae9e9c86v;H9t9v:LZ:Iab9e:b9ExpFF;F:;:I9ebbbbbb;WZ:G:G:G:2k0ed98ababab:Ige:Igdaeae:I:Iae9e:NS87:m:h;n;g8::I9et;N;k;I;5bI:;:G:Iadae9e:Y;79U:jzH:bZ:I9e93:S;l9u9v9v;f:;:G:Iab:G:G:2k:K8Flqud98zul988Jjjjjbc:Wl9Rgv8Kjjjjbcbhoadc99fcK9Tgrcbarcb9kEgwc9O2adfhDdnalcdtc:q:G:cjbfydbgqaicufgkfgdcb9imbawak9RhxdnadTmbaqaifgdceGhmawcdtaicdt9Rc:O:G:cjbfhradc9:GhPavc;adfhdcbhoin9ebbbbbbbbhs9ebbbbbbbbhzdnaxaofgHcb9imbarc98fydb:3hzkadaz85ibdnaHcu9imbarydb:3hskadcwfas85ibadczfhdarcwfhraPaocdfgo9hmbkamTmeaxaofhxkdndnaxcb9omb9ebbbbbbbbhzxekaxcdtyd:G:G:cjb:3hzkavc;adfaocitfaz85ibkaDc9OfhOcbhdaqcbaqcb9kEhmaic;:FFFrGhHaiceGhAaicitavc;adffc9WfhPinadhxdndnaice9omb9ebbbbbbbbhzxekcbhr9ebbbbbbbbhzdnakTmbaPhdabhoinaocwf8Ribad8Rib:Iao8Ribadcwf8Rib:Iaz:G:Ghzadc9WfhdaoczfhoaHarcdfgr9hmbkaATmekabarcitf8Ribavc;adfaxakfar9Rcitf8Rib:Iaz:Ghzkavaxcitfaz85ibaPcwfhPaxcefhdaxam9hmbkaic;:FFFrGhHaiceGhCc8VaD9RhXc8WaD9RhQavc;Gifc98fgLaqcdtfhKawcdtc:G:G:cjbfhwavc;adfc94fhYavc;Gifc9Wfh8Aavc9WfhEaDc9Nfh3aqhxdninavaxcitgdf8Ribhzdnaxce9imbcbhrdndnaxce9hmbaxhdxekaxceGhmaxc;:FFFrGhPaEadfhdcbhravc;Gifhoinaoaz9ebbbbbb9W8::I;8d:3gs9ebbbbbb9W;b:Iaz:G;8dBdbaoclfadcwf8Ribas:Ggz9ebbbbbb9W8::I;8d:3gs9ebbbbbb9W;b:Iaz:G;8dBdbad8Ribas:Ghzaocwfhoadc9WfhdaParcdfgr9hmbkamTmeaxar9Rhdkavc;Gifarcdtfaz9ebbbbbb9W8::I;8d:3gs9ebbbbbb9W;b:Iaz:G;8dBdbavadcitfc94f8Ribas:GhzkazaOz:njjjbgz9ebbbbbb;aZ:I:C9ebbbbbba;a:Iaz:Ggzaz;8dg5:3:HhzdndndndndnaOce9ig8Embavc;Gifaxcdtfc98fgdadydbgdadaQ91gdaQt9RgoBdbaoaX91h8Fada5fh5xekaOmeavc;Gifaxcdtfc98fydbcL91h8Fka8Fce9imdxekcdh8Faz9ebbbbbb;GZ9Mmbcbh8Fxekcehodnaxce9imbcbhrcbhPdnaxceSmbaxceGhaaxc;:FFFrGhAcbhravc;GifhdcbhPinadydbhodndndndnaPTmbcFFFrhPxekaoTmecjjjwhPkadaPao9RBdbcbhPxekcehPkadclfgmydbhodndndndnaPmbcFFFrhPxekaoTmecjjjwhPkamaPao9RBdbcehPcbhoxekcbhPcehokadcwfhdaAarcdfgr9hmbkaaTmekavc;GifarcdtfgrydbhddndnaPTmbcFFFrhoxekcehoadTmecjjjwhokaraoad9RBdbcbhokdna8EmbcFFFihddndna3PdebdkcFFFehdkavc;Gifaxcdtfc98fgrarydbadGBdbka5cefh5a8Fcd9hmb9ebbbbbb;WZaz:Hhzcdh8Faombaz9ebbbbbb;WZaOz:njjjb:Hhzkdnaz9ebbbbbbbb9Imbdnaxaq9mmbaxaq9RgdciGhrcbhoaxhPdndnaqax9Rc980mbadc98Ghma8AaxcdtfhdcbhoaxhPinadydbadclfydbadcwfydbadcxfydbaoVVVVhoadc9WfhdaPc98fhPamc98fgmmbkarTmekaLaPcdtfhdinadydbaoVhoadc98fhdarcufgrmbkkaoTmbavc;Gifaxcdtfc98fhdinaxcufhxaOc9OfhOadydbhoadc98fhdaoTmbxlkkaKhdaxhPinaPcefhPadydbhoadc98fhdaoTmbkaYaiaxfcitfhminavc;adfaxaifgAcitfawaxcefgxcdtfydb:385ibdndnaice9omb9ebbbbbbbbhzxekcbhr9ebbbbbbbbhzdnakTmbamhdabhoinaocwf8Ribad8Rib:Iao8Ribadcwf8Rib:Iaz:G:Ghzadc9WfhdaoczfhoaHarcdfgr9hmbkaCTmekabarcitf8Ribavc;adfaAar9Rcitf8Rib:Iaz:Ghzkavaxcitfaz85ibamcwfhmaxaP9imbkaPhxxekkdndnazcKaD9Rz:njjjbgz9ebbbbbb9Wc9MTmbavc;Gifaxcdtfaz9ebbbbbb9W8::I;8dgd:39ebbbbbb9W;b:Iaz:G;8dBdbaxcefhxaDhOxekaz;8dhdkavc;GifaxcdtfadBdbkdnaxcb9imb9ebbbbbb;WZaOz:njjjbhzdndnaxceGTmbaxhoxekavaxcitfazavc;Gifaxcdtfydb:3:I85ibaxcufhoaz9ebbbbbb9W8::IhzkdnaxTmbaocefhraocdtavc;Giffc98fhdaocitavfc94fhoinaoaz9ebbbbbb9W8::Igsadydb:3:I85ibaocwfazadclfydb:3:I85ibadc94fhdaoc9Wfhoas9ebbbbbb9W8::Ihzarc9:fgrmbkkavaxcitfhHaxhdindndnaqaxadgi9RgAaqaA9iEgdcb9omb9ebbbbbbbbhzxekadcefgociGhrdndnadci9pmbcbhd9ebbbbbbbbhzxekcbhPcbaoc98G9Rhm9ebbbbbbbbhzcbhdinadc1:2:cjbf8RibaHadfgocKf8Rib:Iadcj:2:cjbf8Ribaoczf8Rib:Iadc;4:1:cjbf8Ribaocwf8Rib:Iadc;W:1:cjbf8Ribao8Rib:Iaz:G:G:G:GhzadcafhdamaPc98fgP9hmbkarTmecbaP9Rhdkadcithdinadc;W:1:cjbf8RibaHadf8Rib:Iaz:Ghzadcwfhdarcufgrmbkkavc:GefaAcitfaz85ibaHc94fhHaicufhdaicb9kmbkkdndndndndnalPleddblk9ebbbbbbbbhhdnaxce9imbaxhddnaxceGTmbavc:Gefaxcitfgdc94fgoao8Ribgzad8Ribgs:Ggg85ibadasazag:H:G85ibaxcufhdkaxceSmbadcdfhoadcitavc:Geffc9Wfhdinadad8Ribgsadcwfgr8RibggadczfgH8Ribg8J:Ggz:Gg8K85ibaHa8Jagaz:H:G85ibarazasa8K:H:G85ibadc9Wfhdaoc9:fgocd9kmbkaxceSmbaxcefhoaxcitavc:Geffc94fhdinadad8Ribgzadcwfgr8Ribgs:Ggg85ibarasazag:H:G85ibadc94fhdaocufgocd0mbkaxcefhoavc:Gefaxcitfhd9ebbbbbbbbhhinahad8Rib:Ghhadc94fhdaocufgocd0mbkkav8Ri:Gehza8Fmdaeaz85ibaeah85izaeav8Ri:Oe85iwxikdndnaxcb9omb9ebbbbbbbbhzxekdndnaxciGci9hmb9ebbbbbbbbhzaxhoxekaxcefciGhravc:Gefaxcitfhd9ebbbbbbbbhzaxhoinaocufhoazad8Rib:Ghzadc94fhdarcufgrmbkkaxci6mbaocefhraocitavc:Geffc9OfhdinazadcKf8Rib:Gadczf8Rib:Gadcwf8Rib:Gad8Rib:Ghzadc9Gfhdarc98fgrmbkkaeaz:Aaza8FE85ibxdkdndnaxcb9omb9ebbbbbbbbhzxekdndnaxciGci9hmb9ebbbbbbbbhzaxhoxekaxcefciGhravc:Gefaxcitfhd9ebbbbbbbbhzaxhoinaocufhoazad8Rib:Ghzadc94fhdarcufgrmbkkaxci6mbaocefhraocitavc:Geffc9OfhdinazadcKf8Rib:Gadczf8Rib:Gadcwf8Rib:Gad8Rib:Ghzadc9Gfhdarc98fgrmbkkaeaz:Aaza8FE85ibav8Ri:Geaz:Hhzcehddnaxce9imbaxciGhodnaxcufci6mbaxc;8FFFrGhHavc:Gefcafhdcbhrinazadc9Of8Rib:Gadc9Wf8Rib:Gadc94f8Rib:Gad8Rib:GhzadcafhdaHarclfgr9hmbkaoTmearcefhdkavc:Gefadcitfhdinazad8Rib:Ghzadcwfhdaocufgombkkaeaz:Aaza8FE85iwxekaeaz:A85ibaeah:A85izaeav8Ri:Oe:A85iwkavc:Wlf8Kjjjjba5crGk:ediiue98eu8Jjjjjbcz9Rgd8Kjjjjbdndnab:8gicFFFFrGglc;A:F:K;Ul0mbaeab:7gvav9e:d;i;j9T8W9F;KZ:I9ebbbbbbUJ:G9ebbbbbbU;d:Ggv9ebbb9q;7h;5:;:I:Gav9e9J9I8A9H:0z9r:::I:G85ibav;8dhlxekdnalcjjj;8r6mbaeabab:t:785ibcbhlxekadalalcL4c;Q9:fgocLt9R:::785iwadcwfadaocecbz:kjjjbhlad8Ribhvdnaicu9kmbaeav:A85ibcbal9Rhlxekaeav85ibkadczf8Kjjjjbalk;piiiue99e988Jjjjjbcz9Rge8Kjjjjbdndnab:8gdcFFFFrGgic;A:F:K;6i0mbJbbjZhlaicjjj;mi6meab:7z1jjjbhlxekdnaic;r:N;T:dl0mbdnaic;K:x;Bjl6mb9eKR9e9u;7hDn9eKR9e9u;7hD;aadcb9iEab:7:Gz1jjjb:mhlxdkab:7hvdnadcu9kmbav9eKR9e9u;7h;5Z:Gz:jjjjbhlxdk9eKR9e9u;7h;5Zav:Hz:jjjjbhlxekdnaic;v;J1:hl0mbdnaic;G;B:;:fl6mb9eKR9e9u;7hYn9eKR9e9u;7hY;aadcb9iEab:7:Gz1jjjbhlxdkdnadcu9kmb9e;sh8Zu98;zO;aab:7:Hz:jjjjbhlxdkab:79e;sh8Zu98;zO;a:Gz:jjjjbhlxekdnaicjjj;8r6mbabab:thlxekabaecwfz:ljjjbhiae8RiwhvdndndndnaiciGPlbedibkavz1jjjbhlxikav:Az:jjjjbhlxdkavz1jjjb:mhlxekavz:jjjjbhlkaeczf8Kjjjjbalk:Uebdndnaecjw9imbab9ebbbbbb;Gu:IhbdnaecFs9pmbaec:b94fhexdkab9ebbbbbb;Gu:IhbaecpLaecpL6Ec:c9Wfhexekaec:b949kmbab9ebbbbbb9Gi:Ihbdnaec:49W9nmbaec;jrfhexekab9ebbbbbb9Gi:Ihbaec;W9Oaec;W9O0EcMsfhekabaecFrf:T9c80:g:;:Ikk;mQdbcj:Gdk:WQebbbdbbbbbbbebbbibbblbbblbbbobbb:d;5:Ib9e9o9Ub;88PXb;r9x8Nb;D80;1b9I;B;ab88:z:vbc:qJb9J9r;:b:7;E:Rb:39H;fb869U8Kb;s9n9cb6o;GbD;Q8Ub3M;rb;R5;:b8P:X3b;O8::Nb;181:cb9e:78Ub:C;P:eb:08M9Wbc9:9Fb;w:r85b9t:d85b:C;085b:l9F:eby;5:9b;48F87b;EF:xbs:yvbH8V;Vbq9A:lb9T8F9Tb;p9:BbD;l8NbS9p:3b:E9MZbR;Q9Fb:68N91b;L;R;hb8997;Xb;385rbM9s:kb;79R;Qb8F:X9Fbw9D:nb8Wi9wb97;8Sb;W:R9Rba:8;pbB;0:Ab;J:P5b9E9H:rbwE;Mb:f:zWb:GC9Fb:nn9Obj;yFb8N79nboo8Xb;k9wXb;j:O7b97;I9Gb9R:m;abY;e9hb;n9N;dbD;O;Cb9z:dIb:l4;eb:M3:wb9e:V;DbY9x;rb:L8:vbvrFb8Z9:Zb;c8Y;Ob:y9p;Eb:7998Yb8M89;db8E9R;Vb:F;49Eb818F86bu;Y;kb;X:h5b98:qhbf8K98b;v9U;6b8WR93bX87Jb:1C;gb;dY:Db:T;e;cb8S9ncbxb9Db:g99Sb;JGRb:B;g:Ab8Z9Ibb:0;s98b:0:N:xb839v;vb;x8:;2b:JzKb9n4;8b9K:DIb9W;x:Rb9J98;4b96:W9xbLX;Nb;a69wb87;w;zb:N:eUb8K8J;lb;w:k93b9A9u8Jbb8F:5b;XqEbY;o;Fb:F8XFb9M8Efb:z9x9Hb:S;79hb9:u;ybgW:3b8Y;O:jb;M:;9Gb;V;e;nb2BDb9DZ;ubQ;E;xb9y87;Eb;E:BMb;sgyby:g;Ob;I9y9nb;g;k8Ybw;JQb;G99;lbL;a9qb;Z5:NbK;G9Bb8UA80b:dO9Ib:d9ieb;1:o9Bb:T:Wub8E;P;Yb9i9kJbz9N;tb:Q;D;yb:U9F9cbf9H;obqy:Kb;t:z:0bo:M;Yb9C93ub:J;c:db9H881b:k794b:V:m9Ab9V;x:9bR:M9Jb;0:;;lb:n:b;Vb8M;b9Nb9v;kTb;k;zBby:O;sb;c9H:nbO;j93bl8MCbOS:Bb;e9z;eb;i;f9eb9n:Y:rbbL;Zb;uJ:Tb8P6;Lbp;vzbb::;8b8EN;mb9W;o;UbA8:;1b;S;Xjb:Z;N;db;h;4yb:tvNb;bG8:b8UD:ZbkT;Zb1O:Cb:Ra97b8U:1:Fb9hM;cb978Y8Vbx9v9TbV:N:qb9R;N8Fb8X;l:wb95Q9kbc95;Ib;0;F:jb;ON:xb;I;M:eb:z8X:xb1;T9Rb9F9FBb:7pPb9i:A:0b9N:K2bGV9cb:n9D8Yb:FX:4b:8;LDb:n8X8Lb;3t85b8Wv3bmxeb0w9Ob8S;U9yb9h:Q:qbt;Ndb:9;w8Kb;399:Mb9U9iVb:FQ;Vb:oN:Mb:0:r;2b;r9t9rb;pq;Yba:y8Zb;109:b:Y9J9Ob;D8:9Fbn9Dib:f:jub9v9s8Pb839K;ab9T;yzb8Y9i8Yb9B9m91b9oG;ubT9u9UbkD;bbI;19PbC9M;vb8Nr:Db9Dl9qb:087;Bb;Q4;fb:h;5Lb69R99b58N:6b:w9P8Pb;g;m:Sb:TC9ub:q;Ifb1;z:jb8SV9qbl:K::b93rNb;Z8W9Wbb;88Nb;QG:Ob9M;c6b9K;G89b:x;D:db:JZ:xbJNpbm:g:mb8Xc;EbM85:Db;D9W:mbL:3;Nbw;F87bX838Rb9Cj:Gb9Aj:tbzHMbs;O;yb2j:Vb;BF0bU:qsb9zK4b9I:LXb9H;l:7b;h:j:5bzn:9b;s;Ylb6918Nb;R:2;2b;Bg:7bqC:Qb:j8M8Vb9K:d4bD878ZbPN8Ab9r86:Qb5:J;cb:V;T:Ub9C8MOb9T;c9nbR96:Cb;a9w:xbiZ:dbD;W;2b8Rn:mb9T8X:zb85:0rbxaXb;y;d9Bb;1M;eb;g:T0b9o;k:Lb:N83;nb;M:PBb:RMNb;D9c9ObY9J;Eb4:m;Vb9O:l9sb;8;B83b:U:H:Rb;FX8Xbb:U:Hbx;7;Ab9K9n9Mb;Tv:3b8PW8Wb9x9w:;b9hF86bf;5:5b91::;Zby:t;Fb:Rj8Wb9M:m;2bl;lXb;6gob;z;K5b89:Z:Kb9xE:pbB;nDb9o9c;PbA:::Kb8Z8J:1b;W:Q8Ab9pW:Ob;s;b:LbkZsb9B94;nb8J;54b97:llb:jLVb;g:M9tb9V9U;Ib;V;Rbb:B9k9yb;e;A:3b:Q9M:6b4;p;pb;rd5b:X;XRb:m:z;bb;d:T93b:g9i;Ab;39D:Gb;gj;0b:S;W8Vb;D;S:AbZ9C:8b;q;E9Tb:q;h8FbI;B:2b:J8L86bb:V:Ab:T9t:tb:29xlb8PR:0b0j9:b;Ar:Nb4:QPb979z:HbQOIb;C:3Rb;6;Lpb:j;B;:b:j::pb;K42bo:P;8b8:j9Wb:f9UXbp:hFby8:rb9H9N8ZbIK:gb9n:9;Qb:Z;N:Vb:p9T9Ub:v9N85b8X:;9Bb:e;x9ib8W;FQb;hRJb8L9H81b;j9W;ob8W;l:4b:;2pb:Kb:Ibv2;Kb9A;D:Gbh9V9hb9IO;sb:59C:eb9W9H6b9R9w;Gb:z9seb9q9v83b8E;v:3b8Z;X;ebA9U9Fb9D8W;Kb:f8U:Pb5:Y;db:H8YBbw:3:Kb;Q:X;ubQ;3hb:p9P;Kb8NF93bxijb:nnRb9p;n:Gba:L:zb:Z:I;tb8V9Dqb:0;59cbH;A;lb99::;qb:B;B;bb:RL:9b;k:I:bbwf9Cb8U9vLb8Nb9vbuC;Wb;Hr:gbCk9Kb:wc:nb:h::;Eb;ApIb9R8L:2b97:j80bv;Z;:b:5:;:Eb9Of9pb9kI:Ob9p;e9AbR;4:8b;x9A:yb;0;h:vbm9n:nba86:Mb:K9x9FbCZ:XbjU:vb;maebG;D:gb;j;E:2b:;9G;1b9nWHber9Rb:m:W:Sb:Y;a;qb9r9v9ib8E;7Pb:vV;db:Jo87b;an81bo;C97b;GT;mb9o8P;6b;w;k;ib;O;Zcb989K;Eb:B9K;yb;z::8Xb:K:x;db939y;ub9P;J;fb;W;AAb:68688bSKSb9v919Fb;s:9;1b9UM;gb:S8U9DbP9e;Tb38:9cb9H;e:hb8Pp;Pb;N;w;Zbg98;kb9V:r81bw;G;fbF;x:nb9Uf;Ib:Wp;gb:tw;bb989Dtb9R:T:Yb;n9U:Db8:V97b;gHfb;3;p:Pb8P7;Fb:1;j:6b:3b9rb;I:Ymbt:68Kb;L999Gbt;y:kbmX8Sb:bKxb9:9MNbe8PQb:F964bpp::b9wT;Vb;z9:Bb;S;zAb:l:6:5b;e:x;8b8X:O8Nb;X9U;dbN;fBb;y:O9wb:0:O:1b;p;mPbO:jRb9V9x80b8S9w:jb:z;o;Jb;wa:5b9R9E:Qb8:I:CbH9F;mbpk9kb;H;0;7b:o879Tb;I:g8Sb;P;u:eb;8:0:Pb;V;U;rb8U81;jb8V859HbUh9ebE;z;ib:b;8qb;79kfb8V3;yb9t:0:eb9o:z:mb9ug;mbI9v;Cb;a;g;wbkY:wb8A9W:4b9P:v9Kb8M9A9GbZ9s;UbuHsb;0:1Hb;8;l;1b80:8Rb80:8;Ub;O9D;mb;D9E9Gb9N:o:BbM8Z;Vb;jL:4b9H9y:Bb;H9x:8b9r:d;gb;y8:zb;DG9ibR3;Db:VK:Hbh8SSb9z;Z;xb;z96:yb:E9u;ab9p:g;6b9wo;8b;L95:Ub:jgBbU:Tgb9N:t;Cb9v;O:Qb:c8MUb;k;N:Bb9rm:Kb:z8Z:Xb:P;xPb9Pv9ibW:Y;Wbu1:Nb19m:xb;5;rBbhM:Zb97:c9kb:y;phbn:F;Cb;C9h9vb;Ht86b9N;R9cb;::D;Fb9E;u9Fb979N:Kb:6:S96b9v;2:Ib8R18Jbc:69vb9z9UwbhI:gb859h:db:j;J;Mb;L:E;ub6;7nbF9w;Pb3s;kb;f9z:kbN;68Rb;t;b;fbs;f;pb;B9A:Ub9h;f:gb:fJ9Ibh:g87b8S95Nbz9H:hbI9m97bj8S8AbJ:;Ob18M:qb9488:jb:O;e;Kb;L;B97b;e86;cb8M;0;Qb;39N:kbmM:;bW:J8Rb89:t:Xb:998kb:K9r;Cb8N;D9Jb9P;H;Db:ANYb:O8P:vb9O;oybD;T:0b9e:Fab9o:y;kb9W:c9Jb9:988Jbs:58Yb:N;1:obC9w;Nbh;Xwb:1:DIb9V9:9nb:LY9rb:1;5:Rb:c;F;wb:w;D9HbQBdb;e86:Fb:d:I:HbV;T9Tb85:n96b:c:4:Pb9R8Y9CbS8N9Bbb80;Tb;sb93b;8;09vbe9z9nb;GGjbbbbbbbbbbbbn;7h;5ZbbbbR9et8:bbbj:yS;488bbb9G9r;m9487bbbj:dE;W85bbbna8L96Ubbbjg:c;JBbbbb5;Z9P81bc:W:2dkxebbbdbbbn:Bbb",e=new Uint8Array([32,0,65,2,1,106,34,33,3,128,11,4,13,64,6,253,10,7,15,116,127,5,8,12,40,16,19,54,20,9,27,255,113,17,42,67,24,23,146,148,18,14,22,45,70,69,56,114,101,21,25,63,75,136,108,28,118,29,73,115]);if(typeof WebAssembly!="object")return{supported:!1};var t,a=WebAssembly.instantiate(i(n),{}).then(function(h){t=h.instance,t.exports.__wasm_call_ctors()});function i(h){for(var d=new Uint8Array(h.length),f=0;f<h.length;++f){var b=h.charCodeAt(f);d[f]=b>96?b-97:b>64?b-39:b+4}for(var p=0,f=0;f<h.length;++f)d[p++]=d[f]<60?e[d[f]]:(d[f]-60)*64+d[++f];return d.buffer.slice(0,p)}function r(h){if(!h)throw new Error("Assertion failed")}function s(h){return new Uint8Array(h.buffer,h.byteOffset,h.byteLength)}function o(h,d,f,b,p,g,m,u,y,x){var v=t.exports.sbrk,E=v(d*16),_=h?v(h.byteLength):0,A=v(f.byteLength),k=v(g.byteLength),w=v(u.byteLength),M=new Uint8Array(t.exports.memory.buffer);h&&M.set(s(h),_),M.set(s(f),A),M.set(s(g),k),M.set(s(u),w),t.exports.meshopt_generateTangents(E,_,d,A,b,p*4,k,m*4,w,y*4,x),M=new Uint8Array(t.exports.memory.buffer);var R=new Float32Array(M.buffer,E,d*4).slice();return v(E-v(0)),R}function c(h,d,f,b,p,g,m){var u=t.exports.sbrk,y=u(d*12),x=h?u(h.byteLength):0,v=u(f.byteLength),E=new Uint8Array(t.exports.memory.buffer);h&&E.set(s(h),x),E.set(s(f),v),t.exports.meshopt_generateNormals(y,x,d,v,b,p*4,g,m),E=new Uint8Array(t.exports.memory.buffer);var _=new Float32Array(E.buffer,y,d*3).slice();return u(y-u(0)),_}var l={Compatible:1,ZeroFallback:2};return{ready:a,supported:!0,generateTangents:function(h,d,f,b,p,g,m,u){r(h===null||h instanceof Uint32Array||h instanceof Int32Array||h instanceof Uint16Array||h instanceof Int16Array),r(h===null||h.length%3==0),r(d instanceof Float32Array),r(d.length%f==0),r(f>=3),r(b instanceof Float32Array),r(b.length%p==0),r(p>=3),r(g instanceof Float32Array),r(g.length%m==0),r(m>=2),r(d.length/f==b.length/p),r(d.length/f==g.length/m),r(h!==null||d.length/f%3==0);for(var y=0,x=0;x<(u?u.length:0);++x)r(u[x]in l),y|=l[u[x]];var v=d.length/f,E=h?h.length:v,_=h===null||h.BYTES_PER_ELEMENT==4?h:new Uint32Array(h);return o(_,E,d,v,f,b,p,g,m,y)},generateNormals:function(h,d,f,b,p){r(h===null||h instanceof Uint32Array||h instanceof Int32Array||h instanceof Uint16Array||h instanceof Int16Array),r(h===null||h.length%3==0),r(d instanceof Float32Array),r(d.length%f==0),r(f>=3),r(h!==null||d.length/f%3==0),r(b>=0&&b<=Math.PI),p=p||0;var g=d.length/f,m=h?h.length:g,u=h===null||h.BYTES_PER_ELEMENT==4?h:new Uint32Array(h);return c(u,m,d,g,f,b,p)}}})();const Ud=.02;let Fd=!1;Pr.ready.then(()=>{Fd=!0},()=>{});function Ld(){return Fd&&Pr.supported}function Qx(n,e,t){if(!Ld())return null;if(t>=1)return n;const a=Math.max(3,3*Math.floor(n.length/3*t)),[i]=Pr.simplify(Uint32Array.from(n),e,3,a,Ud);return i.length>=3?i:n}function jd(n,e,t){const a=[],i=r=>e[t?t[r]:r]===1;for(let r=0;r<n.length;r+=3)(i(n[r])||i(n[r+1])||i(n[r+2]))&&a.push(n[r],n[r+1],n[r+2]);return Uint32Array.from(a)}async function Od(n,e){const t=await Bt(await fetch(`api/${n}/${e}/appearance.bin`)),{meta:a,arrays:i}=_i(await t.arrayBuffer());if(a.kind!=="appearance")throw new Error("not an appearance bundle");const r=o=>i[o].data,s=await Promise.all(a.images.map((o,c)=>createImageBitmap(new Blob([i[`image${c}`].data],{type:o.mimeType}),{premultiplyAlpha:"none",colorSpaceConversion:"none"})));return{name:a.name,drawn:a.drawn,welded:i.welded.data,normals:r("normals"),uvs:Array.from({length:a.uvSets},(o,c)=>r(`uv${c}`)),colors:a.colors?r("colors"):null,parts:a.parts.map((o,c)=>({material:o.material,triangles:i[`triangles${c}`].data})),materials:a.materials,images:s}}const Yh={9728:dt,9729:na,9984:Ul,9985:rr,9986:ci,9987:Ba},Zh={33071:za,33648:gr,10497:pr};function $x(n){return Array.isArray(n)?n.length===9?new Pe().fromArray(n):n.length===4?new ot().fromArray(n):n.length===3?new O().fromArray(n):new De().fromArray(n):n}class e0{constructor(e,t,a){this.appearance=e,this.geometry=this.drawnGeometry(t.vertices),this.geometry.setAttribute("vid",new Be(Float32Array.from(e.welded),1));const i=new Be(new Float32Array(this.geometry.getAttribute("position").array),3);if(i.setUsage(Xl),this.geometry.setAttribute("displaced",i),this.reduced=t.reduced?{REDUCED:1}:{},t.reduced)for(const[r,s]of Object.entries(md(t.reduced,e.welded)))this.geometry.setAttribute(r,s);this.useDetail(1),this.shared={deformed:{value:null},deformedWidth:{value:a},deformedNormalWeight:{value:.4},wire:{value:!1}},this.gpuMaterials=e.parts.map(r=>this.material(r.material,this.reduced)),this.cpuMaterials=e.parts.map(r=>this.material(r.material,{CPU_PATH:1})),this.mesh=new Nt(this.geometry,this.gpuMaterials),this.mesh.frustumCulled=!1}appearance;geometry;mesh;gpuMaterials;cpuMaterials;textures=new Map;shared;detail=new Map;only=new WeakMap;reduced;drawnGeometry(e,t={}){const{appearance:a}=this,i=new pt;for(const[o,[c,l]]of Object.entries({position:[e,3],...t}))i.setAttribute(o,new Be(this.gathered(c,l),l));i.setAttribute("normal",new Be(a.normals,3)),i.setAttribute("texcoord0",new Be(a.uvs[0]??new Float32Array(a.drawn*2),2)),a.uvs[1]&&i.setAttribute("texcoord1",new Be(a.uvs[1],2)),a.colors&&i.setAttribute("vertexColor",new Be(a.colors,4));const r=this.triangles(1,i.getAttribute("position").array);i.setIndex(r.index);let s=0;return r.counts.forEach((o,c)=>{i.addGroup(s,o,c),s+=o}),i}materialsWith(e){return this.appearance.parts.map(t=>this.material(t.material,{},e))}gathered(e,t){const a=this.appearance.welded,i=new Float32Array(a.length*t);for(let r=0;r<a.length;r++)for(let s=0;s<t;s++)i[t*r+s]=e[t*a[r]+s];return i}setTile(e,t,a){if(this.mesh.material=t?this.cpuMaterials:this.gpuMaterials,this.shared.deformed.value=e,this.shared.deformedNormalWeight.value=a,t){const i=this.geometry.getAttribute("displaced"),r=i.array,s=this.appearance.welded;for(let o=0;o<s.length;o++){const c=3*s[o];r[3*o]=t[c],r[3*o+1]=t[c+1],r[3*o+2]=t[c+2]}i.needsUpdate=!0}for(const i of this.mesh.material)i.uniformsNeedUpdate=!0}useDetail(e){let t=this.detail.get(e);if(!t){if(e<1&&!Ld())return this.useDetail(1);t=this.triangles(e,this.geometry.getAttribute("position").array),this.detail.set(e,t)}this.useLevel(t)}drawOnly(e){let t=this.only.get(e);if(!t){const a=this.detail.get(1),i=a.index.array,r=[];let s=0;for(const c of a.counts)r.push(jd(i.subarray(s,s+c),e,this.appearance.welded)),s+=c;const o=new Uint32Array(r.reduce((c,l)=>c+l.length,0));r.reduce((c,l)=>(o.set(l,c),c+l.length),0),t={index:new Be(o,1),counts:r.map(c=>c.length)},this.only.set(e,t)}this.useLevel(t)}useLevel(e){if(this.geometry.index===e.index)return;this.geometry.setIndex(e.index),this.geometry.clearGroups();let t=0;e.counts.forEach((a,i)=>{this.geometry.addGroup(t,a,i),t+=a})}dispose(){this.geometry.dispose();for(const e of[...this.gpuMaterials,...this.cpuMaterials])e.dispose();for(const e of this.textures.values())e.dispose()}triangles(e,t){const a=e<1?a0(this.appearance):null,i=this.appearance.parts.map(o=>{if(!a||o.triangles.length<300)return o.triangles;const c=Math.max(3,3*Math.floor(o.triangles.length/3*e)),[l]=Pr.simplifyWithAttributes(Uint32Array.from(o.triangles),t,3,a,fi,t0,null,c,Ud,["LockBorder"]);return l.length>=3?l:o.triangles}),r=new Uint32Array(i.reduce((o,c)=>o+c.length,0));let s=0;for(const o of i)r.set(o,s),s+=o.length;return{index:new Be(r,1),counts:i.map(o=>o.length)}}material(e,t,a){const i=this.appearance.materials[e].shading,r={...this.shared};for(const[o,c]of Object.entries(i.uniforms))r[o]={value:$x(c)};for(const[o,c]of Object.entries(i.textures))r[o]={value:this.texture(c.image,c.srgb,c.sampler)};const s=a?Jt:xi;return new s({glslVersion:Ea,vertexShader:a??Wo,fragmentShader:qo,defines:{...i.defines,...t},uniforms:r,side:i.doubleSided?Kt:Ma,transparent:i.blend,depthWrite:!i.blend})}texture(e,t,a){const i=`${e} ${t} ${JSON.stringify(a)}`;let r=this.textures.get(i);return r||(r=new _t(this.appearance.images[e]),r.flipY=!1,r.colorSpace=t?kt:ga,r.magFilter=Yh[a.magFilter],r.minFilter=Yh[a.minFilter],r.generateMipmaps=a.minFilter>=9984,r.wrapS=Zh[a.wrapS],r.wrapT=Zh[a.wrapT],r.needsUpdate=!0,this.textures.set(i,r)),r}}const fi=5,t0=[1,1,.5,.5,.5];function a0(n){const e=n.uvs[0],t=n.normals,a=new Float32Array(n.drawn*fi);for(let i=0;i<n.drawn;i++){e&&(a[fi*i]=e[2*i],a[fi*i+1]=e[2*i+1]);for(let r=0;r<3;r++)a[fi*i+2+r]=t[3*i+r]}return a}const n0=128*2**20;class i0{constructor(e,t,a,i,r,s){this.options=e,this.motion=t,this.viewer=a,this.transport=i,this.busy=r,this.problem=s}options;motion;viewer;transport;busy;problem;meshId="";songId="";loading=null;dropped=null;items=null;onBasis=()=>{};onMenus=()=>{};get meshName(){return this.items?.meshes.find(e=>e.id===this.meshId)?.name??""}get songName(){return this.items?.songs.find(e=>e.id===this.songId)?.name??""}get mappings(){return this.items?.mappings??[]}async refresh(){const e=await yl();this.items=e,Zy(e);const t=I("mesh"),a=t.value;xs(t,e.meshes,this.loading??this.meshId),r0(t,e.rigs??[]),[...t.options].some(s=>s.value===a)?t.value=a:e.meshes.length||(t.prepend(new Option("no model: drop one, or choose a rig","",!0,!0)),t.options[0].disabled=!0),xs(I("song"),e.songs,this.songId);const i=I("mapping-menu"),r=i.value;xs(i,e.mappings,r),(i.closest("label")??i).hidden=!e.mappings.length,I("remove-mapping").hidden=!e.mappings.length;for(const[s,o]of[["mesh",e.meshes.length],["song",e.songs.length]]){const c=I(`remove-${s}`);c.disabled=Number(o)<2,c.title=c.disabled?`the only ${s==="mesh"?"model":"song"}: add another before removing it`:`remove this ${s==="mesh"?"model":"song"} from the library (its file on disk stays)`}return this.onMenus(),e}drop(e){e===this.loading&&(this.dropped=e)}async loadMesh(e){const t=this.items?.meshes.find(a=>a.id===e);if(!t)throw new Error(`the server has no model with id ${e}`);this.loading=e,I("mesh").value=e;try{!t.ready&&t.job&&await this.followSolve(t.name,t.job),this.busy(`${t.name}: loading its harmonics…`,null);const a=16*Math.ceil(t.k/4)*t.vertices,[i,r]=await Promise.all([lf(e,this.options.half??a>n0),t.look?Od("meshes",e).catch(s=>(this.problem(`${t.name}: its materials cannot be shown (${wa(s)}); it is drawn in clay`),null)):null]);return this.viewer.setBasis(i,this.options.batch,r),I("materials-switch").hidden=!r,this.motion.basis=i,this.meshId=e,I("mesh").value=e,this.onBasis(),!0}catch(a){if(this.dropped===e)return!1;throw a}finally{this.loading=this.dropped=null,I("mesh").value=this.meshId,this.busy(null)}}async followSolve(e,t){let a=t;const i=performance.now(),r=()=>{const o=` · ${Math.floor((performance.now()-i)/1e3)} s`,c=a.done>0&&(!a.cached||a.done<a.total),l=a.state==="queued"?"waiting for the model before it":c?`computing its harmonics (${a.done} of ${a.total})`:a.cached?"reading its harmonics from the cache":"preparing its harmonics (the Laplacian, the first band)";this.busy(`${e}: ${l}${o}`,c?a.done/a.total:null)};r();const s=setInterval(r,1e3);try{await To(t.id,o=>{a=o,r()})}finally{clearInterval(s)}}async loadSong(e){const t=this.items?.songs.find(a=>a.id===e)?.name??"the song";try{this.busy(`${t}: loading…`,null);const a=await df(e);if(this.motion.setSpectrum(a),this.songId=e,I("song").value=e,I("seek").max=String(a.duration),this.options.render){await this.transport.load(null,a.duration);return}try{await this.transport.load(await ff(e),a.duration)}catch(i){await this.transport.load(null,a.duration),this.problem(`${t}: this browser cannot play its sound (${wa(i)})`)}}finally{this.onMenus(),document.body.classList.contains("live")||(I("song").value=this.songId),this.busy(null)}}}function xs(n,e,t){n.innerHTML="";for(const a of e)n.add(new Option(a.name,a.id,!1,a.id===t))}function r0(n,e){if(!e.length)return;const t=document.createElement("optgroup");t.label="rigs (vibration modes)";for(const a of e)t.appendChild(new Option(a.name,`rig:${a.id}`));n.appendChild(t)}const Qh="eigendance-help-seen";class s0{pausedHint=null;status(e){this.pausedHint=null,this.show(e)}hint(e,t){this.status(t?"":e),this.pausedHint=t?null:e}playing(e){e&&this.pausedHint!==null&&I("status").textContent===this.pausedHint&&this.status("")}error(e){I("error-text").textContent=e,I("error").hidden=!1}clearError(){I("error").hidden=!0}shownError(){return I("error").hidden?null:I("error-text").textContent}loading(e,t=null){if(I("loading").hidden=e===null,e===null)return;I("loading-text").textContent=e;const a=I("loading-progress");t===null?a.removeAttribute("value"):a.value=t}async guard(e,t){try{return await t(),null}catch(a){const i=`${e}: ${wa(a)}`;return this.error(i),this.status(""),i}}help(e){if(I("help").hidden=!e,!e)try{localStorage.setItem(Qh,"1")}catch{}}helpOnFirstVisit(){let e=null;try{e=localStorage.getItem(Qh)}catch{}e||this.help(!0)}wire(){I("help-button").addEventListener("click",()=>this.help(!0)),I("help-close").addEventListener("click",()=>this.help(!1)),I("help").addEventListener("click",e=>{e.target===I("help")&&this.help(!1)}),I("error-close").addEventListener("click",()=>this.clearError())}show(e){const t=I("status");t.textContent=e,t.title=e}}const o0=30;class c0{constructor(e,t,a,i){this.bands=e,this.rate=t,this.envelope=i,this.out=new Float32Array(0),this.smooth=new Float64Array(e),this.follow=new Float64Array(e);const r=s=>s>0?Math.exp(-1/(t*s)):0;this.memory=r(a),this.rise=Array.from(i.attack,r),this.fall=Array.from(i.release,r),this.low=new Float64Array(e),this.span=new Float64Array(e).fill(1),this.ring=i.autoRange?Math.round(o0*t):0,this.recent=new Float32Array(this.ring*e)}bands;rate;envelope;done=0;out;smooth;follow;rise;fall;memory;low;span;rangedAt=-1/0;recent;ring;extend(e,t){const a=this.bands;if(this.out.length<e.length){const s=new Float32Array(e.length);s.set(this.out),this.out=s}const i=this.memory,r=this.envelope;for(let s=this.done;s<t;s++){r.autoRange&&s-this.rangedAt>=this.rate&&this.range(s);for(let o=0;o<a;o++){this.smooth[o]=i*this.smooth[o]+(1-i)*e[s*a+o];let c=this.smooth[o];r.autoRange&&(this.recent[s%this.ring*a+o]=c,c=this.span[o]<=1e-6?0:Math.min(1,Math.max(0,(c-this.low[o])/this.span[o]))),c<r.threshold[o]&&(c=0);const l=c>this.follow[o]?this.rise[o]:this.fall[o];this.follow[o]=c+l*(this.follow[o]-c),this.out[s*a+o]=r.identity?this.smooth[o]:this.follow[o]}}return this.done=Math.max(this.done,t),this.out}range(e){this.rangedAt=e;const t=Math.max(0,e-this.ring);if(e-t<2)return;const a=new Float64Array(e-t);for(let i=0;i<this.bands;i++){for(let s=t;s<e;s++)a[s-t]=this.recent[s%this.ring*this.bands+i];a.sort();const r=s=>{const o=s/100*(a.length-1),c=Math.floor(o),l=Math.min(c+1,a.length-1);return a[c]+(o-c)*(a[l]-a[c])};this.low[i]=r(5),this.span[i]=r(95)-this.low[i]}}}const h0=4,$h=n=>n.live===!0;class l0{basis=null;spectrum=null;smoothedValues=new Map;buffer=new Float32Array(0);heard=new WeakMap;loudest=null;get ready(){return this.basis!==null&&this.spectrum!==null}get songLoaded(){return this.spectrum!==null}get duration(){return this.spectrum?.duration??0}setSpectrum(e){this.spectrum=e,this.smoothedValues.clear()}bandValuesAt(e,t){const a=this.spectrum;if(t){const i=this.heardBy(t);return jh(a,e,i.buffer,i.values)}return this.buffer.length!==a.bands&&(this.buffer=new Float32Array(a.bands)),jh(a,e,this.buffer,a.values)}sectionGain(e,t){return this.spectrum?qy(e,this.spectrum.sections,t):1}kick(e,t){if(!(e.pulse.amount>0)||!this.spectrum)return 0;const a=this.heardBy(e);return xo(e.pulse,a.events,t,a.accents)}heardBy(e){const t=this.spectrum;let a=this.heard.get(e);if(!a||a.spectrum!==t){const i=$h(t),r=Oh(t,e.pulse);a={spectrum:t,values:i?t.values:this.valuesFor(e),buffer:new Float32Array(t.bands),events:r,accents:zh(t,e.pulse,r)},i&&(e.smoothing>0||!e.envelope.identity)&&(a.shaper=new c0(t.bands,t.rate,e.smoothing,e.envelope)),this.heard.set(e,a)}return $h(t)&&a.revision!==t.revision&&(a.revision=t.revision,a.values=a.shaper?a.shaper.extend(t.values,t.frames):t.values,a.events=Oh(t,e.pulse),a.accents=zh(t,e.pulse,a.events)),a}loudestTimes(e){const t=this.spectrum;if(this.loudest?.spectrum===t&&this.loudest.count===e)return this.loudest.times;const{frames:a,bands:i,values:r,rate:s}=t,o=new Float64Array(a);for(let h=0;h<a;h++)for(let d=0;d<i;d++)o[h]+=r[h*i+d];const c=Array.from({length:a},(h,d)=>d).sort((h,d)=>o[d]-o[h]),l=[];for(const h of c){if(l.length===e)break;l.every(d=>Math.abs(d-h/s)>=.25)&&l.push(h/s)}return this.loudest={spectrum:t,count:e,times:l},l}prepare(e){return Ir(e,this.basis.k)}weights(e,t){const a=Ko(e,this.bandValuesAt(t,e),e.gain*this.sectionGain(e,t),void 0,this.kick(e,t));return Xy(this.basis,a)}valuesFor(e){const t=this.spectrum,a=e.envelope;if(!(e.smoothing>0)&&a.identity)return t.values;let i=this.smoothedValues.get(a.key);return i?this.smoothedValues.delete(a.key):(i=Gy(Hy(t,e.smoothing),t.frames,t.bands,t.rate,a),this.smoothedValues.size>=h0&&this.smoothedValues.delete(this.smoothedValues.keys().next().value)),this.smoothedValues.set(a.key,i),i}}const el=[{id:"gain",key:"gain",shown:n=>`${n.toFixed(2)}×`},{id:"smoothing",key:"smoothing",shown:n=>`${n.toFixed(2)} s`},{id:"facets",key:"deformedNormalWeight",shown:n=>n.toFixed(2)}];class d0{constructor(e,t){this.motion=e,this.events=t,this.wireControls()}motion;events;mapping=null;prepared=null;source="";explorer={harmonic:-1,scale:1};show(e,t=""){this.mapping=e,this.source=t,this.prepared=this.motion.basis?this.motion.prepare(e):null;const a=_r(e);for(const{id:i,key:r,shown:s}of el)I(i).value=String(a[r]),I(`${i}-out`).textContent=s(a[r]);I("shading").value=a.shading,I("materials").checked=a.materials,I("player-source").textContent=t}shot(e){if(!this.mapping||!this.prepared)return null;const{shading:t,deformedNormalWeight:a,materials:i}=_r(this.mapping);return{element:e,prepared:this.prepared,look:{shading:t,deformedNormalWeight:a,materials:i},source:this.mapping}}saved(){return this.mapping?pd(Lh(this.mapping,this.settings()),this.motion.basis):null}basisChanged(){const e=this.motion.basis.k;this.mapping&&(this.prepared=this.motion.prepare(this.mapping)),this.explorer.harmonic=-1,this.explorer.scale=1;const t=I("harmonic");t.value="-1",t.max=String(e-1)}refreshInfo(e){const t=this.motion.basis;if(!t)return;const a=this.explorer.harmonic,i=a>=0?` · harmonic ${a}: λ = ${t.eigenvalues[a].toPrecision(4)}`:"";I("player-info").textContent=`${t.name}: ${t.n} vertices, k = ${t.k}, ${e.toUpperCase()} deformation${i}`}settings(){const e=t=>Number(I(t).value);return{gain:e("gain"),smoothing:e("smoothing"),deformedNormalWeight:e("facets"),shading:I("shading").value,materials:I("materials").checked}}apply(){this.mapping&&(Object.assign(this.mapping,Lh(this.mapping,this.settings())),this.prepared=this.motion.prepare(this.mapping),this.events.requestDraw())}wireControls(){for(const{id:t,shown:a}of el){const i=I(t);i.addEventListener("input",()=>{I(`${t}-out`).textContent=a(Number(i.value)),this.apply()})}I("shading").addEventListener("change",()=>this.apply()),I("materials").addEventListener("change",()=>this.apply());const e=I("harmonic");e.addEventListener("input",()=>this.explore(e.value)),I("save-mapping").addEventListener("click",()=>{const t=this.saved();t&&Ei(t,Wa(this.events.modelName(),this.source,"json"))}),I("load-mapping").addEventListener("change",t=>{const a=t.target,i=a.files?.[0];i&&this.events.upload(i),a.value=""})}explore(e){const t=this.motion.basis?.k??1,a=Math.min(t-1,Math.max(-1,Math.floor(Number(e))));this.explorer.harmonic=Number.isFinite(a)?a:-1,this.explorer.scale=this.explorer.harmonic>=0?this.events.harmonicScale(this.explorer.harmonic):1,this.events.requestDraw()}}var ws={exports:{}},tl;function f0(){return tl||(tl=1,(function(n){(function(e,t){n.exports?n.exports=t():window.ysFixWebmDuration=t()})("fix-webm-duration",function(){var e={172351395:{name:"EBML",type:"Container"},646:{name:"EBMLVersion",type:"Uint"},759:{name:"EBMLReadVersion",type:"Uint"},754:{name:"EBMLMaxIDLength",type:"Uint"},755:{name:"EBMLMaxSizeLength",type:"Uint"},642:{name:"DocType",type:"String"},647:{name:"DocTypeVersion",type:"Uint"},645:{name:"DocTypeReadVersion",type:"Uint"},108:{name:"Void",type:"Binary"},63:{name:"CRC-32",type:"Binary"},190023271:{name:"SignatureSlot",type:"Container"},16010:{name:"SignatureAlgo",type:"Uint"},16026:{name:"SignatureHash",type:"Uint"},16037:{name:"SignaturePublicKey",type:"Binary"},16053:{name:"Signature",type:"Binary"},15963:{name:"SignatureElements",type:"Container"},15995:{name:"SignatureElementList",type:"Container"},9522:{name:"SignedElement",type:"Binary"},139690087:{name:"Segment",type:"Container"},21863284:{name:"SeekHead",type:"Container"},3515:{name:"Seek",type:"Container"},5035:{name:"SeekID",type:"Binary"},5036:{name:"SeekPosition",type:"Uint"},88713574:{name:"Info",type:"Container"},13220:{name:"SegmentUID",type:"Binary"},13188:{name:"SegmentFilename",type:"String"},1882403:{name:"PrevUID",type:"Binary"},1868715:{name:"PrevFilename",type:"String"},2013475:{name:"NextUID",type:"Binary"},1999803:{name:"NextFilename",type:"String"},1092:{name:"SegmentFamily",type:"Binary"},10532:{name:"ChapterTranslate",type:"Container"},10748:{name:"ChapterTranslateEditionUID",type:"Uint"},10687:{name:"ChapterTranslateCodec",type:"Uint"},10661:{name:"ChapterTranslateID",type:"Binary"},710577:{name:"TimecodeScale",type:"Uint"},1161:{name:"Duration",type:"Float"},1121:{name:"DateUTC",type:"Date"},15273:{name:"Title",type:"String"},3456:{name:"MuxingApp",type:"String"},5953:{name:"WritingApp",type:"String"},103:{name:"Timecode",type:"Uint"},6228:{name:"SilentTracks",type:"Container"},6359:{name:"SilentTrackNumber",type:"Uint"},39:{name:"Position",type:"Uint"},43:{name:"PrevSize",type:"Uint"},35:{name:"SimpleBlock",type:"Binary"},32:{name:"BlockGroup",type:"Container"},33:{name:"Block",type:"Binary"},34:{name:"BlockVirtual",type:"Binary"},13729:{name:"BlockAdditions",type:"Container"},38:{name:"BlockMore",type:"Container"},110:{name:"BlockAddID",type:"Uint"},37:{name:"BlockAdditional",type:"Binary"},27:{name:"BlockDuration",type:"Uint"},122:{name:"ReferencePriority",type:"Uint"},123:{name:"ReferenceBlock",type:"Int"},125:{name:"ReferenceVirtual",type:"Int"},36:{name:"CodecState",type:"Binary"},13730:{name:"DiscardPadding",type:"Int"},14:{name:"Slices",type:"Container"},104:{name:"TimeSlice",type:"Container"},76:{name:"LaceNumber",type:"Uint"},77:{name:"FrameNumber",type:"Uint"},75:{name:"BlockAdditionID",type:"Uint"},78:{name:"Delay",type:"Uint"},79:{name:"SliceDuration",type:"Uint"},72:{name:"ReferenceFrame",type:"Container"},73:{name:"ReferenceOffset",type:"Uint"},74:{name:"ReferenceTimeCode",type:"Uint"},47:{name:"EncryptedBlock",type:"Binary"},106212971:{name:"Tracks",type:"Container"},46:{name:"TrackEntry",type:"Container"},87:{name:"TrackNumber",type:"Uint"},13253:{name:"TrackUID",type:"Uint"},3:{name:"TrackType",type:"Uint"},57:{name:"FlagEnabled",type:"Uint"},8:{name:"FlagDefault",type:"Uint"},5546:{name:"FlagForced",type:"Uint"},28:{name:"FlagLacing",type:"Uint"},11751:{name:"MinCache",type:"Uint"},11768:{name:"MaxCache",type:"Uint"},254851:{name:"DefaultDuration",type:"Uint"},216698:{name:"DefaultDecodedFieldDuration",type:"Uint"},209231:{name:"TrackTimecodeScale",type:"Float"},4991:{name:"TrackOffset",type:"Int"},5614:{name:"MaxBlockAdditionID",type:"Uint"},4974:{name:"Name",type:"String"},177564:{name:"Language",type:"String"},6:{name:"CodecID",type:"String"},9122:{name:"CodecPrivate",type:"Binary"},362120:{name:"CodecName",type:"String"},13382:{name:"AttachmentLink",type:"Uint"},1742487:{name:"CodecSettings",type:"String"},1785920:{name:"CodecInfoURL",type:"String"},438848:{name:"CodecDownloadURL",type:"String"},42:{name:"CodecDecodeAll",type:"Uint"},12203:{name:"TrackOverlay",type:"Uint"},5802:{name:"CodecDelay",type:"Uint"},5819:{name:"SeekPreRoll",type:"Uint"},9764:{name:"TrackTranslate",type:"Container"},9980:{name:"TrackTranslateEditionUID",type:"Uint"},9919:{name:"TrackTranslateCodec",type:"Uint"},9893:{name:"TrackTranslateTrackID",type:"Binary"},96:{name:"Video",type:"Container"},26:{name:"FlagInterlaced",type:"Uint"},5048:{name:"StereoMode",type:"Uint"},5056:{name:"AlphaMode",type:"Uint"},5049:{name:"OldStereoMode",type:"Uint"},48:{name:"PixelWidth",type:"Uint"},58:{name:"PixelHeight",type:"Uint"},5290:{name:"PixelCropBottom",type:"Uint"},5307:{name:"PixelCropTop",type:"Uint"},5324:{name:"PixelCropLeft",type:"Uint"},5341:{name:"PixelCropRight",type:"Uint"},5296:{name:"DisplayWidth",type:"Uint"},5306:{name:"DisplayHeight",type:"Uint"},5298:{name:"DisplayUnit",type:"Uint"},5299:{name:"AspectRatioType",type:"Uint"},963876:{name:"ColourSpace",type:"Binary"},1029411:{name:"GammaValue",type:"Float"},230371:{name:"FrameRate",type:"Float"},97:{name:"Audio",type:"Container"},53:{name:"SamplingFrequency",type:"Float"},14517:{name:"OutputSamplingFrequency",type:"Float"},31:{name:"Channels",type:"Uint"},15739:{name:"ChannelPositions",type:"Binary"},8804:{name:"BitDepth",type:"Uint"},98:{name:"TrackOperation",type:"Container"},99:{name:"TrackCombinePlanes",type:"Container"},100:{name:"TrackPlane",type:"Container"},101:{name:"TrackPlaneUID",type:"Uint"},102:{name:"TrackPlaneType",type:"Uint"},105:{name:"TrackJoinBlocks",type:"Container"},109:{name:"TrackJoinUID",type:"Uint"},64:{name:"TrickTrackUID",type:"Uint"},65:{name:"TrickTrackSegmentUID",type:"Binary"},70:{name:"TrickTrackFlag",type:"Uint"},71:{name:"TrickMasterTrackUID",type:"Uint"},68:{name:"TrickMasterTrackSegmentUID",type:"Binary"},11648:{name:"ContentEncodings",type:"Container"},8768:{name:"ContentEncoding",type:"Container"},4145:{name:"ContentEncodingOrder",type:"Uint"},4146:{name:"ContentEncodingScope",type:"Uint"},4147:{name:"ContentEncodingType",type:"Uint"},4148:{name:"ContentCompression",type:"Container"},596:{name:"ContentCompAlgo",type:"Uint"},597:{name:"ContentCompSettings",type:"Binary"},4149:{name:"ContentEncryption",type:"Container"},2017:{name:"ContentEncAlgo",type:"Uint"},2018:{name:"ContentEncKeyID",type:"Binary"},2019:{name:"ContentSignature",type:"Binary"},2020:{name:"ContentSigKeyID",type:"Binary"},2021:{name:"ContentSigAlgo",type:"Uint"},2022:{name:"ContentSigHashAlgo",type:"Uint"},206814059:{name:"Cues",type:"Container"},59:{name:"CuePoint",type:"Container"},51:{name:"CueTime",type:"Uint"},55:{name:"CueTrackPositions",type:"Container"},119:{name:"CueTrack",type:"Uint"},113:{name:"CueClusterPosition",type:"Uint"},112:{name:"CueRelativePosition",type:"Uint"},50:{name:"CueDuration",type:"Uint"},4984:{name:"CueBlockNumber",type:"Uint"},106:{name:"CueCodecState",type:"Uint"},91:{name:"CueReference",type:"Container"},22:{name:"CueRefTime",type:"Uint"},23:{name:"CueRefCluster",type:"Uint"},4959:{name:"CueRefNumber",type:"Uint"},107:{name:"CueRefCodecState",type:"Uint"},155296873:{name:"Attachments",type:"Container"},8615:{name:"AttachedFile",type:"Container"},1662:{name:"FileDescription",type:"String"},1646:{name:"FileName",type:"String"},1632:{name:"FileMimeType",type:"String"},1628:{name:"FileData",type:"Binary"},1710:{name:"FileUID",type:"Uint"},1653:{name:"FileReferral",type:"Binary"},1633:{name:"FileUsedStartTime",type:"Uint"},1634:{name:"FileUsedEndTime",type:"Uint"},4433776:{name:"Chapters",type:"Container"},1465:{name:"EditionEntry",type:"Container"},1468:{name:"EditionUID",type:"Uint"},1469:{name:"EditionFlagHidden",type:"Uint"},1499:{name:"EditionFlagDefault",type:"Uint"},1501:{name:"EditionFlagOrdered",type:"Uint"},54:{name:"ChapterAtom",type:"Container"},13252:{name:"ChapterUID",type:"Uint"},5716:{name:"ChapterStringUID",type:"String"},17:{name:"ChapterTimeStart",type:"Uint"},18:{name:"ChapterTimeEnd",type:"Uint"},24:{name:"ChapterFlagHidden",type:"Uint"},1432:{name:"ChapterFlagEnabled",type:"Uint"},11879:{name:"ChapterSegmentUID",type:"Binary"},11964:{name:"ChapterSegmentEditionUID",type:"Uint"},9155:{name:"ChapterPhysicalEquiv",type:"Uint"},15:{name:"ChapterTrack",type:"Container"},9:{name:"ChapterTrackNumber",type:"Uint"},0:{name:"ChapterDisplay",type:"Container"},5:{name:"ChapString",type:"String"},892:{name:"ChapLanguage",type:"String"},894:{name:"ChapCountry",type:"String"},10564:{name:"ChapProcess",type:"Container"},10581:{name:"ChapProcessCodecID",type:"Uint"},1293:{name:"ChapProcessPrivate",type:"Binary"},10513:{name:"ChapProcessCommand",type:"Container"},10530:{name:"ChapProcessTime",type:"Uint"},10547:{name:"ChapProcessData",type:"Binary"},39109479:{name:"Tags",type:"Container"},13171:{name:"Tag",type:"Container"},9152:{name:"Targets",type:"Container"},10442:{name:"TargetTypeValue",type:"Uint"},9162:{name:"TargetType",type:"String"},9157:{name:"TagTrackUID",type:"Uint"},9161:{name:"TagEditionUID",type:"Uint"},9156:{name:"TagChapterUID",type:"Uint"},9158:{name:"TagAttachmentUID",type:"Uint"},10184:{name:"SimpleTag",type:"Container"},1443:{name:"TagName",type:"String"},1146:{name:"TagLanguage",type:"String"},1156:{name:"TagDefault",type:"Uint"},1159:{name:"TagString",type:"String"},1157:{name:"TagBinary",type:"Binary"}};function t(h,d){h.prototype=Object.create(d.prototype),h.prototype.constructor=h}function a(h,d){this.name=h||"Unknown",this.type=d||"Unknown"}a.prototype.updateBySource=function(){},a.prototype.setSource=function(h){this.source=h,this.updateBySource()},a.prototype.updateByData=function(){},a.prototype.setData=function(h){this.data=h,this.updateByData()};function i(h,d){a.call(this,h,d||"Uint")}t(i,a);function r(h){return h.length%2===1?"0"+h:h}i.prototype.updateBySource=function(){this.data="";for(var h=0;h<this.source.length;h++){var d=this.source[h].toString(16);this.data+=r(d)}},i.prototype.updateByData=function(){var h=this.data.length/2;this.source=new Uint8Array(h);for(var d=0;d<h;d++){var f=this.data.substr(d*2,2);this.source[d]=parseInt(f,16)}},i.prototype.getValue=function(){return parseInt(this.data,16)},i.prototype.setValue=function(h){this.setData(r(h.toString(16)))};function s(h,d){a.call(this,h,d||"Float")}t(s,a),s.prototype.getFloatArrayType=function(){return this.source&&this.source.length===4?Float32Array:Float64Array},s.prototype.updateBySource=function(){var h=this.source.reverse(),d=this.getFloatArrayType(),f=new d(h.buffer);this.data=f[0]},s.prototype.updateByData=function(){var h=this.getFloatArrayType(),d=new h([this.data]),f=new Uint8Array(d.buffer);this.source=f.reverse()},s.prototype.getValue=function(){return this.data},s.prototype.setValue=function(h){this.setData(h)};function o(h,d){a.call(this,h,d||"Container")}t(o,a),o.prototype.readByte=function(){return this.source[this.offset++]},o.prototype.readUint=function(){for(var h=this.readByte(),d=8-h.toString(2).length,f=h-(1<<7-d),b=0;b<d;b++)f*=256,f+=this.readByte();return f},o.prototype.updateBySource=function(){for(this.data=[],this.offset=0;this.offset<this.source.length;this.offset=f){var h=this.readUint(),d=this.readUint(),f=Math.min(this.offset+d,this.source.length),b=this.source.slice(this.offset,f),p=e[h]||{name:"Unknown",type:"Unknown"},g=a;switch(p.type){case"Container":g=o;break;case"Uint":g=i;break;case"Float":g=s;break}var m=new g(p.name,p.type);m.setSource(b),this.data.push({id:h,idHex:h.toString(16),data:m})}},o.prototype.writeUint=function(h,d){for(var f=1,b=128;h>=b&&f<8;f++,b*=128);if(!d)for(var p=b+h,g=f-1;g>=0;g--){var m=p%256;this.source[this.offset+g]=m,p=(p-m)/256}this.offset+=f},o.prototype.writeSections=function(h){this.offset=0;for(var d=0;d<this.data.length;d++){var f=this.data[d],b=f.data.source,p=b.length;this.writeUint(f.id,h),this.writeUint(p,h),h||this.source.set(b,this.offset),this.offset+=p}return this.offset},o.prototype.updateByData=function(){var h=this.writeSections("draft");this.source=new Uint8Array(h),this.writeSections()},o.prototype.getSectionById=function(h){for(var d=0;d<this.data.length;d++){var f=this.data[d];if(f.id===h)return f.data}return null};function c(h){o.call(this,"File","File"),this.setSource(h)}t(c,o),c.prototype.fixDuration=function(h,d){var f=d&&d.logger;f===void 0?f=function(u){console.log(u)}:f||(f=function(){});var b=this.getSectionById(139690087);if(!b)return f("[fix-webm-duration] Segment section is missing"),!1;var p=b.getSectionById(88713574);if(!p)return f("[fix-webm-duration] Info section is missing"),!1;var g=p.getSectionById(710577);if(!g)return f("[fix-webm-duration] TimecodeScale section is missing"),!1;var m=p.getSectionById(1161);if(m)if(m.getValue()<=0)f(`[fix-webm-duration] Duration section is present, but the value is ${m.getValue()}`),m.setValue(h);else return f(`[fix-webm-duration] Duration section is present, and the value is ${m.getValue()}`),!1;else f("[fix-webm-duration] Duration section is missing"),m=new s("Duration","Float"),m.setValue(h),p.data.push({id:1161,data:m});return g.setValue(1e6),p.updateByData(),b.updateByData(),this.updateByData(),!0},c.prototype.toBlob=function(h){return new Blob([this.source.buffer],{type:h||"video/webm"})};function l(h,d,f,b){if(typeof f=="object"&&(b=f,f=void 0),!f)return new Promise(function(g){l(h,d,g,b)});try{var p=new FileReader;p.onloadend=function(){try{var g=new c(new Uint8Array(p.result));g.fixDuration(d,b)&&(h=g.toBlob(h.type))}catch{}f(h)},p.readAsArrayBuffer(h)}catch{f(h)}}return l.default=l,l})})(ws)),ws.exports}var u0=f0();const b0=Rd(u0),m0=["video/webm;codecs=vp9,opus","video/webm;codecs=vp8,opus","video/webm"];function p0(n,e,t){const a=i=>Math.max(16,2*Math.round(i*t/2));return{width:a(n),height:a(e)}}class g0{constructor(e,t,a,i){this.transport=e,this.buttons=t,this.play=a,this.shown=i,t.forEach(r=>r.addEventListener("click",()=>this.toggle()))}transport;buttons;play;shown;recorder=null;frame=null;source=null;started=0;stopped=0;get recording(){return this.recorder!==null}get size(){return this.frame?{width:this.frame.canvas.width,height:this.frame.canvas.height}:null}toggle(){if(this.recorder){this.stopped=performance.now(),this.recorder.stop();return}const e=this.shown(),t=e.name,a=e.element.getBoundingClientRect(),{width:i,height:r}=p0(a.width,a.height,Math.min(devicePixelRatio,2)),s=document.createElement("canvas");s.width=i,s.height=r,this.frame={canvas:s,context:s.getContext("2d")},this.source=e,e.viewer.onDrawn=()=>this.copy(),e.viewer.requestDraw();const o=s.captureStream(30),c=this.transport.tap();c.stream.getAudioTracks().forEach(f=>o.addTrack(f));const l=m0.find(f=>MediaRecorder.isTypeSupported(f))??"video/webm",h=[],d=new MediaRecorder(o,{mimeType:l});d.ondataavailable=f=>{f.data.size&&h.push(f.data)},d.onstop=async()=>{const f=this.stopped-this.started;this.transport.untap(c),this.source&&(this.source.viewer.onDrawn=()=>{}),this.recorder=null,this.frame=this.source=null,this.buttons.forEach(g=>{g.textContent="● record"});const b=new Blob(h,{type:"video/webm"}),p=await b0(b,f,{logger:!1}).catch(()=>b);ko(p,Wa(t,"dance","webm"))},this.started=performance.now(),d.start(250),this.recorder=d,this.buttons.forEach(f=>{f.textContent="■ stop"}),this.play()}copy(){const{frame:e,source:t}=this;if(!e||!t)return;const a=t.viewer.bufferRect(t.element);a.width<1||a.height<1||e.context.drawImage(t.viewer.renderer.domElement,a.x,a.y,a.width,a.height,0,0,e.canvas.width,e.canvas.height)}}const Xt=new O(.42,.28,1).normalize(),v0=1.08;class y0{backdrop;shadow;backdropMaterial;shadowMaterial;constructor(){this.backdropMaterial=new xi({glslVersion:Ea,vertexShader:Cy,fragmentShader:Iy,uniforms:{top:{value:new Ve(2830395)},bottom:{value:new Ve(1184792)},aspect:{value:1}},depthTest:!1,depthWrite:!1}),this.backdrop=new Nt(new Bn(2,2),this.backdropMaterial),this.backdrop.frustumCulled=!1,this.backdrop.renderOrder=-2,this.shadowMaterial=new xi({glslVersion:Ea,vertexShader:Py,fragmentShader:Dy,uniforms:{strength:{value:.55}},transparent:!0,depthWrite:!1}),this.shadow=new Nt(new Bn(2,2).rotateX(-Math.PI/2),this.shadowMaterial),this.shadow.renderOrder=-1}placeShadow(e){const t=new ln().setFromBufferAttribute(new Be(e.vertices,3)),a=t.getSize(new O);this.shadow.position.set((t.min.x+t.max.x)/2,t.min.y-.01*a.y,(t.min.z+t.max.z)/2),this.shadow.scale.set(.62*a.x+.05,1,.62*a.z+.05)}setAspect(e){this.backdropMaterial.uniforms.aspect.value=e}dispose(){this.backdrop.geometry.dispose(),this.shadow.geometry.dispose(),this.backdropMaterial.dispose(),this.shadowMaterial.dispose()}}function zd(n){const e=n.clone().normalize(),t=new O(0,1,0).cross(e).normalize();return[e,t,e.clone().cross(t)]}function nn(n,e){const[t,a,i]=zd(e),r=n.length/3,s=new Float32Array(r),o=new Float32Array(r),c=new Float32Array(r);for(let l=0;l<r;l++){const h=n[3*l],d=n[3*l+1],f=n[3*l+2];s[l]=h*t.x+d*t.y+f*t.z,o[l]=h*a.x+d*a.y+f*a.z,c[l]=h*i.x+d*i.y+f*i.z}return{s,x:o,y:c}}function x0(n,e){const t=n.x.length,[a,i]=Bd([n]),r=new Float32Array(t);for(let o=0;o<t;o++)r[o]=n.s[o]+Math.max(Math.abs(n.x[o]-a),Math.abs(n.y[o]-i));const s=Array.from({length:t},(o,c)=>c).sort((o,c)=>r[c]-r[o]);return Int32Array.from(s.slice(0,Math.max(1,Math.ceil(e*t))))}function Bd(n){let e=1/0,t=-1/0,a=1/0,i=-1/0;for(const r of n)for(let s=0;s<r.x.length;s++)e=Math.min(e,r.x[s]),t=Math.max(t,r.x[s]),a=Math.min(a,r.y[s]),i=Math.max(i,r.y[s]);return[(e+t)/2,(a+i)/2]}function Gd(n,e,t,a){const[,i,r]=zd(e),[s,o]=Bd(n),c=Math.tan(Kl.degToRad(t)/2)/v0,l=c*a;let h=0;for(const d of n)for(let f=0;f<d.x.length;f++){const b=Math.max(Math.abs(d.y[f]-o)/c,Math.abs(d.x[f]-s)/l);h=Math.max(h,d.s[f]+b)}return{target:i.multiplyScalar(s).add(r.multiplyScalar(o)),distance:h}}const w0=.3,M0=32,_0=.25,E0=.5,ar=.45,S0=1.7,A0=.08,Wt=20,T0=.8,k0=1.6,R0=1.5,C0=["top-right","top-left","bottom-right","bottom-left"];function Dr(n,e){const t=[1/0,1/0,-1/0,-1/0],a=e?e.length:n.x.length;for(let i=0;i<a;i++){const r=e?e[i]:i;t[0]=Math.min(t[0],n.x[r]),t[1]=Math.min(t[1],n.y[r]),t[2]=Math.max(t[2],n.x[r]),t[3]=Math.max(t[3],n.y[r])}return t}function I0(n,e,t,a,i,r){const s=new Float32Array(e.length),o=new Float32Array(e.length),c=new Float32Array(e.length);return e.forEach((l,h)=>{s[h]=n.s[l]-r,o[h]=t+i*(n.x[l]-t),c[h]=a+i*(n.y[l]-a)}),{s,x:o,y:c}}function P0(n,e,t=Xt,a=null){const i=n.length/3,r=new Float32Array(i);for(const y of e)for(let x=0;x<i;x++)r[x]=Math.max(r[x],Math.hypot(y[3*x]-n[3*x],y[3*x+1]-n[3*x+1],y[3*x+2]-n[3*x+2]));const s=r.reduce((y,x)=>Math.max(y,x),0);if(!(s>0))return null;const o=nn(n,t),c=U0(o,r,r.indexOf(s),w0*s,a),[l,h,d,f]=Dr(o),b=Hd([o,...e.map(y=>nn(y,t))],c),p=Math.max(d-l,1e-9),g=Math.max(f-h,1e-9),m=N0(n,e,c,a,t),u=Vd(t,m);return{...D0([n,...e].map(y=>nn(y,u)),c,A0*Math.max(p,g)),direction:u,turn:m,count:c.length,share:Math.max(b[2]-b[0],b[3]-b[1])/Math.max(p,g),box:[(b[0]-l)/p,(b[1]-h)/g,(b[2]-l)/p,(b[3]-h)/g]}}function Hd(n,e){const t=[1/0,1/0,-1/0,-1/0];for(const a of n){const i=Dr(a,e);t[0]=Math.min(t[0],i[0]),t[1]=Math.min(t[1],i[1]),t[2]=Math.max(t[2],i[2]),t[3]=Math.max(t[3],i[3])}return t}function D0(n,e,t){const a=Hd(n,e);let i=-1/0,r=1/0;for(const p of n)for(const g of e)i=Math.max(i,p.s[g]),r=Math.min(r,p.s[g]);const s=(i+r)/2,o=(a[0]+a[2])/2,c=(a[1]+a[3])/2,l=Math.max(a[2]-a[0],a[3]-a[1],1e-9),h=Math.max(S0,t/l),d=k0*h*l,[f]=n,b=Uint8Array.from(f.x,(p,g)=>+(Math.abs(p-o)<d&&Math.abs(f.y[g]-c)<d));return{shapes:n.map(p=>I0(p,e,o,c,h,s)),depth:s,front:i-s,visible:b}}function Vd(n,e){return n.clone().applyAxisAngle(new O(0,1,0),e*Math.PI/2)}function N0(n,e,t,a,i=Xt){if(!a)return 0;const r=new Float32Array(n.length),s=new O,o=new O,c=new O;for(let p=0;p<a.length;p+=3){s.fromArray(n,3*a[p]),o.fromArray(n,3*a[p+1]).sub(s),c.fromArray(n,3*a[p+2]).sub(s),o.cross(c);for(let g=0;g<3;g++)for(let m=0;m<3;m++)r[3*a[p+g]+m]+=o.getComponent(m)}const l=new O,h=new O,d=p=>{let g=0;for(const m of t){l.fromArray(r,3*m).normalize();let u=0;for(const y of e)h.fromArray(y,3*m).sub(s.fromArray(n,3*m)),u=Math.max(u,h.addScaledVector(p,-h.dot(p)).length());g+=Math.max(0,l.dot(p))*u}return g};let f=0,b=R0*d(i);for(const p of[1,2,3]){const g=d(Vd(i,p));g>b&&(f=p,b=g)}return f}function U0(n,e,t,a,i){const r=Int32Array.from(e.keys()),s=u=>{for(;r[u]!==u;)u=r[u]=r[r[u]];return u},o=(u,y)=>{r[s(u)]=s(y)},c=u=>e[u]>a;if(i)for(let u=0;u<i.length;u+=3)for(let y=0;y<3;y++){const x=i[u+y],v=i[u+(y+1)%3];c(x)&&c(v)&&o(x,v)}const[l,h,d,f]=Dr(n),b=Math.max(d-l,f-h,1e-9)/M0,p=Math.floor((d-l)/b)+3,g=new Map;e.forEach((u,y)=>{if(!c(y))return;const x=(Math.floor((n.y[y]-h)/b)+1)*p+Math.floor((n.x[y]-l)/b)+1,v=g.get(x);v===void 0?g.set(x,y):o(y,v)});for(const[u,y]of g)for(const x of[u+1,u+p-1,u+p,u+p+1]){const v=g.get(x);v!==void 0&&o(y,v)}const m=s(t);return Int32Array.from(e.keys()).filter(u=>c(u)&&s(u)===m)}const Ms=new O;function F0(n){const e=n.endsWith("left"),t=n.startsWith("top");return[e?0:1-ar,t?1-ar:0,e?ar:1,t?1:ar]}function L0(n,e,t=Xt){const a=nn(n,t),[i,r,s,o]=Dr(a),c=new Uint8Array(Wt*Wt),l=(d,f,b)=>Math.min(Wt-1,Math.floor(Wt*(d-f)/Math.max(b-f,1e-9)));for(let d=0;d<a.x.length;d++)c[l(a.y[d],r,o)*Wt+l(a.x[d],i,s)]=1;const h=d=>{const[f,b,p,g]=F0(d),m=e[0]<p&&e[2]>f&&e[1]<g&&e[3]>b;let u=0;for(let y=0;y<Wt;y++)for(let x=0;x<Wt;x++){const v=(x+.5)/Wt,E=(y+.5)/Wt;v>f&&v<p&&E>b&&E<g&&(u+=c[y*Wt+x])}return u+(m?Wt*Wt:0)};return C0.reduce((d,f)=>h(f)<h(d)?f:d)}function j0(n,e,t=Xt,a=null){const i=P0(n,e,t,a);return!i||i.share>=(i.turn?E0:_0)?null:{...i,corner:L0(n,i.box,t)}}function O0(n,e){return j0(n.vertices,e.map(t=>Va(n,t)),Xt,n.faces)}class z0{camera;framings=new WeakMap;constructor(e){this.camera=new Pt(e,1,.001,100)}draw(e,t,a,i,r){const s=i.element.getBoundingClientRect();if(s.width<2||s.height<2)return;const o=s.left,c=r-s.bottom;e.setViewport(o,c,s.width,s.height),e.setScissor(o,c,s.width,s.height),e.clearDepth();const l=Math.round(s.width/s.height*50)/50;let h=this.framings.get(i.closeUp);h||this.framings.set(i.closeUp,h=new Map);let d=h.get(l);d||(d=Gd(i.closeUp.shapes,i.closeUp.direction,this.camera.fov,l),h.set(l,d));const f=this.camera;f.aspect=l;const{depth:b,front:p,direction:g}=i.closeUp;f.near=Math.max(T0*(d.distance-p),d.distance/100),f.far=d.distance+10,Ms.copy(g).multiplyScalar(b).add(d.target),f.position.copy(g).multiplyScalar(d.distance).add(Ms),f.lookAt(Ms),f.updateProjectionMatrix(),a.setAspect(l),t.drawOnly(i.closeUp.visible),e.render(t.scene,f),t.drawOnly(null)}}const ur=1024;class al{constructor(e,t){this.source=e,this.tiles=t;const{basis:a}=e;this.width=Math.min(a.n,ur),this.height=Math.ceil(a.n/this.width);const i=Ny(t);this.material=new Jt({glslVersion:Ea,defines:{K4:a.k4,WEIGHTS:3*a.k4*t,TILES:t},uniforms:{harmonics:{value:e.texture},texWidth:{value:e.textureWidth},weights:{value:new Float32Array(12*a.k4*t)},targetWidth:{value:this.width},targetSize:{value:new De(this.width,this.height)}},vertexShader:Xo+i.vertex,fragmentShader:i.fragment,depthTest:!1,depthWrite:!1});const r=new pt;r.setAttribute("position",e.geometry.getAttribute("position")),r.setAttribute("vid",e.geometry.getAttribute("vid"));const s=new Mr(r,this.material);s.frustumCulled=!1,this.scene.add(s)}source;tiles;material;scene=new Ho;targets=[];width;height;camera=new Bo(-1,1,1,-1,0,1);target(e){for(;this.targets.length<=e;)this.targets.push(new Sa(this.width,this.height,{type:zt,format:Rt,depthBuffer:!1,minFilter:dt,magFilter:dt,generateMipmaps:!1,count:this.tiles}));return this.targets[e]}run(e,t=0){const a=this.material.uniforms.weights.value;a.fill(0),e.forEach((c,l)=>a.set(c,l*c.length)),this.material.uniformsNeedUpdate=!0;const i=this.target(t),r=this.source.renderer,s=r.getRenderTarget(),o=r.getScissorTest();return r.setScissorTest(!1),r.setRenderTarget(i),r.render(this.scene,this.camera),r.setRenderTarget(s),r.setScissorTest(o),i.textures.slice(0,e.length)}read(e,t=0){const a=this.source.renderer,i=a.getContext(),r=this.target(t),s=new Float32Array(this.width*this.height*4),o=a.getRenderTarget();a.setRenderTarget(r),i.readBuffer(i.COLOR_ATTACHMENT0+e),i.readPixels(0,0,this.width,this.height,i.RGBA,i.FLOAT,s),i.readBuffer(i.COLOR_ATTACHMENT0),a.setRenderTarget(o);const c=this.source.basis.n,l=new Float32Array(c*3);for(let h=0;h<c;h++)l[3*h]=s[4*h],l[3*h+1]=s[4*h+1],l[3*h+2]=s[4*h+2];return l}dispose(){this.material.dispose(),this.targets.forEach(e=>e.dispose())}}const ec=14263423;function B0(n){const e=n.getContext(),t=e.getParameter(e.MAX_VERTEX_UNIFORM_VECTORS);return 4*Math.floor((t-32)/3)}class G0{constructor(e,t,a=8){this.basis=e,this.renderer=t;const i=t.getContext(),r=i.getParameter(i.MAX_TEXTURE_SIZE),s=Fr(e)*e.k4,o=Math.min(r,4096,s),c=Math.ceil(s/o);if(this.textureWidth=o,c>r)throw new Error(`basis too large for a ${r}² texture`);const l=new Float32Array(o*c*4);l.set(e.harmonics),this.texture=new ud(l,o,c,Rt,zt),this.texture.internalFormat="RGBA32F",this.texture.minFilter=this.texture.magFilter=dt,this.texture.generateMipmaps=!1,this.texture.needsUpdate=!0,this.geometry=new pt,this.geometry.setAttribute("position",new Be(e.vertices,3)),this.geometry.setIndex(new Be(e.faces,1)),this.detailIndex.set(1,this.geometry.index),this.geometry.computeVertexNormals();const h=new Float32Array(e.n).map((u,y)=>y);this.geometry.setAttribute("vid",new Be(h,1));const d=new Be(new Float32Array(e.vertices),3);if(d.setUsage(Xl),this.geometry.setAttribute("displaced",d),e.reduced){for(const[u,y]of Object.entries(md(e.reduced)))this.geometry.setAttribute(u,y);this.samples={basis:{...e,n:e.reduced.m},renderer:t,texture:this.texture,textureWidth:o,geometry:Ly(e.reduced.m)}}const f=e.reduced?{K4:e.k4,HARMONICS:1,REDUCED:1}:{K4:e.k4,HARMONICS:1},b=()=>({harmonics:{value:this.texture},texWidth:{value:o},colorHarmonic:{value:-1},colorScale:{value:1},baseColor:{value:new Ve(ec)},deformedNormalWeight:{value:.4},wire:{value:!1}}),p=u=>new xi({glslVersion:Ea,defines:{...f,...u},uniforms:b(),vertexShader:Xo+Wo,fragmentShader:qo,side:Kt});this.gpuMaterial=p({}),this.cpuMaterial=p({CPU_PATH:1}),this.gpuMaterial.uniforms.deformed={value:null},this.gpuMaterial.uniforms.deformedWidth={value:Math.min(Fr(e),ur)};const g=i.getParameter(i.MAX_VERTEX_UNIFORM_VECTORS),m=i.getParameter(i.MAX_DRAW_BUFFERS);this.batch=Math.max(1,Math.min(a,m,Math.floor(Math.min(g-32,1024)/(3*e.k4)))),this.mesh=new Nt(this.geometry,this.gpuMaterial),this.mesh.frustumCulled=!1,this.scene.add(this.mesh)}basis;renderer;geometry;texture;gpuMaterial;cpuMaterial;mesh;look=null;shown=!0;scene=new Ho;textureWidth;batch;single=null;batched=null;samples=null;gather=null;detailIndex=new Map;detail=1;partIndex=new WeakMap;useCPU=!1;get material(){return this.useCPU?this.cpuMaterial:this.gpuMaterial}setLook(e){this.look&&(this.scene.remove(this.look.mesh),this.look.dispose()),this.look=e?new e0(e,this.basis,this.gpuMaterial.uniforms.deformedWidth.value):null,this.look&&this.scene.add(this.look.mesh)}setTile(e,t,a,i=null){const r=a.materials&&!a.wireframe&&a.harmonic<0?this.look:null;if(this.mesh.visible=this.shown&&!r,r){r.mesh.visible=this.shown;const c=this.useCPU?null:i??this.computePositions([e])[0];r.setTile(c,this.useCPU?t:null,a.deformedNormalWeight);return}this.look&&(this.look.mesh.visible=!1);const s=this.material;this.mesh.material=s;const o=s.uniforms;if(o.baseColor.value.setHex(a.color,kt),o.deformedNormalWeight.value=a.deformedNormalWeight,o.colorHarmonic.value=a.harmonic,o.colorScale.value=a.harmonicScale,o.wire.value=a.wireframe,s.wireframe=a.wireframe,s.uniformsNeedUpdate=!0,this.useCPU||(o.deformed.value=i??this.computePositions([e])[0]),this.useCPU&&t){const c=this.geometry.getAttribute("displaced");c.array.set(t),c.needsUpdate=!0}}useDetail(e){let t=this.detailIndex.get(e);if(!t){const a=Qx(this.basis.faces,this.basis.vertices,e);if(!a)return this.useDetail(1);t=new Be(a,1),this.detailIndex.set(e,t)}return this.geometry.index!==t&&this.geometry.setIndex(t),this.look?.useDetail(e),this.detail=e,e}drawOnly(e){if(!e){this.useDetail(this.detail);return}let t=this.partIndex.get(e);t||(t=new Be(jd(this.basis.faces,e),1),this.partIndex.set(e,t)),this.geometry.setIndex(t),this.look?.drawOnly(e)}computePositions(e){const t=this.samples??this;if(e.length===1)return this.single??=new al(t,1),this.single.run(e);this.batched??=new al(t,this.batch);const a=[];for(let i=0,r=0;i<e.length;i+=this.batch,r++)a.push(...this.batched.run(e.slice(i,i+this.batch),r));return a}readPositions(e,t=0){const a=this.computePositions(e);return this.samples?this.gathered(a[t]):e.length===1?this.single.read(0):this.batched.read(t%this.batch,Math.floor(t/this.batch))}readAll(e){if(e.length===1)return[this.readPositions(e)];const t=this.computePositions(e);return this.samples?t.map(a=>this.gathered(a)):e.map((a,i)=>this.batched.read(i%this.batch,Math.floor(i/this.batch)))}gathered(e){return this.gather??=new jy(this.geometry,this.basis.n,ur,Math.min(Fr(this.basis),ur),this.texture,this.textureWidth,this.basis.k4),this.gather.read(this.renderer,e)}harmonicScale(e){const{n:t,k4:a,harmonics:i}=this.basis,r=this.basis.reduced?zy(this.basis,e):null;let s=0;for(let o=0;o<t;o++)s=Math.max(s,Math.abs(r?r[o]:i[o*4*a+e]));return s>0?1/s:1}dispose(){this.geometry.dispose(),this.texture.dispose(),this.gpuMaterial.dispose(),this.cpuMaterial.dispose(),this.look?.dispose(),this.single?.dispose(),this.batched?.dispose(),this.samples?.geometry.dispose(),this.gather?.dispose()}}function H0(n,e){const{meta:t,arrays:a}=_i(n);if(t.kind!=="rig")throw new Error("not a rig bundle");const i=s=>a[s].data,r=s=>a[s].data;return{id:e,name:t.name,revision:t.revision,edited:!!t.edited,n:t.n,m:t.faces,b:t.bodies,j:t.joints,k:t.modes,G:t.groups,center:t.center,diagonal:t.diagonal,jointList:t.joint_list,bodyNames:t.body_names,palette:t.palette,offset:t.offset??0,vertices:i("vertices"),faces:r("faces"),tau:i("tau"),frequencies:i("frequencies"),amplitudes:i("amplitudes"),tileAmplitudes:i("tile_amplitudes"),reach:i("reach"),phases:i("phases"),skinJoints:r("skin_joints"),skinWeights:i("skin_weights"),boneMatrices:i("bone_matrices"),bindMatrices:i("bind_matrices"),bodyCenters:i("body_centers"),bodyRotations:i("body_rotations"),bodyEnds:i("body_ends"),bodyTwists:i("body_twists"),jointBodies:r("joint_bodies"),jointPositions:i("joint_positions"),jointBend:i("joint_bend")}}function wi(n,e){const t=`${(n*e).toFixed(2)} Hz`;return Math.abs(e-1)<.005?t:`${t} (×${e.toFixed(2)} time scale)`}const Er={low:.4,high:1.5};function nl(n,e){if(!(n>0))return{timeScale:e,label:wi(n,e)};const t=Math.min(Er.high,Math.max(Er.low,n*e));return Math.abs(t-n*e)<1e-9?{timeScale:e,label:wi(n,e)}:{timeScale:t/n,label:`${n.toFixed(2)} Hz, shown at ${t.toFixed(2)} Hz`}}function il(n){const e=[...new Set(Array.from(n))].sort((a,i)=>a-i),t=[];for(let a=0;a<e.length;){let i=a;for(;i+1<e.length&&e[i+1]===e[i]+1;)i++;t.push(i>a?`${e[a]+1}–${e[i]+1}`:`${e[a]+1}`),a=i+1}return t.length?`${e.length===1?"mode":"modes"} ${t.join(", ")}`:"still"}function ki(n){return n.diagonal>0?2/n.diagonal:1}function Wd(n){const e=ki(n),t=new Float32Array(n.n*3);for(let a=0;a<n.n;a++)for(let i=0;i<3;i++)t[3*a+i]=(n.vertices[3*a+i]-n.center[i])*e;return{name:n.name,n:n.n,k:12*n.G,k4:3*n.G,vertices:t,faces:n.faces,eigenvalues:new Float32Array(0),coefficients:new Float32Array(0),harmonics:n.tau}}function _s(n,e){const t=ki(n);for(let a=0;a<n.n;a++)for(let i=0;i<3;i++)e[3*a+i]=e[3*a+i]/t+n.center[i];return e}async function Nr(n,e,t){const a=t===void 0?void 0:{method:"POST",headers:{"Content-Type":"application/json"},body:JSON.stringify(t)},i=await Bt(await fetch(n,a));return H0(await i.arrayBuffer(),e)}const V0=n=>Nr(`api/rigs/${n}/rig.bin`,n),W0=(n,e,t)=>Nr(`api/rigs/${n}/pose`,n,{joint:e,rotation:t}),q0=(n,e)=>Nr(`api/rigs/${n}/stiffness`,n,{joints:e}),X0=n=>Nr(`api/rigs/${n}/reset`,n,{});async function rl(n,e,t){return cn("api/rig-gallery",{rig:n,song:e})}function K0(n){const{meta:e,arrays:t}=_i(n);if(e.kind!=="rig-surface")throw new Error("not a rig surface bundle");return{n:e.n,k:e.k,G:e.groups,harmonics:t.harmonics.data,coefficients:t.coefficients.data}}async function J0(n){const e=await Bt(await fetch(`api/rigs/${n}/surface.bin`));return K0(await e.arrayBuffer())}async function Y0(n,e,t=8){return(await cn("api/rig-surface-gallery",{rig:n,song:e,size:t})).mappings}function Z0(n,e){const t=Wd(n),a=3*n.G+e.G,i=4*a,r=12*n.G,s=new Float32Array(n.n*i);for(let o=0;o<n.n;o++)s.set(n.tau.subarray(o*r,(o+1)*r),o*i),s.set(e.harmonics.subarray(o*4*e.G,(o+1)*4*e.G),o*i+r);return{...t,k:4*a,k4:a,harmonics:s}}function Q0(n,e,t,a){const i=ki(n);for(let r=0;r<e.G;r++){const s=3*n.G+r;for(let o=0;o<3;o++)for(let c=0;c<4;c++){const l=4*r+c;a[12*s+4*o+c]=l<e.k?(t[l]-1)*e.coefficients[3*l+o]*i:0}}return a}function $0(n){const e=4*n.G;return Array.from({length:n.k},(t,a)=>{const i=new Float32Array(3*n.n);for(let r=0;r<n.n;r++){const s=n.harmonics[r*e+a];for(let o=0;o<3;o++)i[3*r+o]=s*n.coefficients[3*a+o]}return i})}class qd{constructor(e,t,a=1){this.surface=e,this.mapping=t,this.gain=a,this.prepared=Ir(t,e.k)}surface;mapping;gain;prepared;phi(e,t){return e.spectrum?Ko(this.prepared,e.bandValuesAt(t,this.prepared),this.prepared.gain*this.gain*e.sectionGain(this.prepared,t),void 0,e.kick(this.prepared,t)):new Float64Array(this.surface.k).fill(1)}genes(){return{...this.mapping,gain:(this.mapping.gain??1)*this.gain}}}function ew(n,e,t){let a=0,i=0;for(const r of e){const s=Va(n,t(r,!0)),o=Va(n,t(r,!1));for(let c=0;c<s.length;c++)a+=(s[c]-n.vertices[c])**2,i+=(s[c]-o[c])**2}return a>0?Math.sqrt(i/a):0}const sl=`
#include <common>
#include <skinning_pars_vertex>
#include <morphtarget_pars_vertex>
out vec3 vViewPosition;
out vec3 vNormal;
#ifdef MATERIAL
in vec2 texcoord0;
out vec2 vUv0;
#ifdef UV1
in vec2 texcoord1;
out vec2 vUv1;
#endif
#ifdef VERTEX_COLOR
in vec4 vertexColor;
out vec4 vColor;
#endif
#endif
void main() {
  #include <skinbase_vertex>
  #include <begin_vertex>
  #include <morphtarget_vertex>
  #include <skinning_vertex>
#ifdef MATERIAL
  vUv0 = texcoord0;
#ifdef UV1
  vUv1 = texcoord1;
#endif
#ifdef VERTEX_COLOR
  vColor = vertexColor;
#endif
#endif
  vec4 mv = modelViewMatrix * vec4(transformed, 1.0);
  vViewPosition = -mv.xyz;
  vNormal = normalize(normalMatrix * normal);
  gl_Position = projectionMatrix * mv;
}
`;function ol(n,e){e.length&&(n.morphAttributes.position=e.map(t=>new Be(t,3)),n.morphTargetsRelative=!0)}class tw{constructor(e,t=null,a=null){this.rig=e;const i=ki(e);this.group.matrixAutoUpdate=!1,this.group.matrix.makeScale(i,i,i).setPosition(-e.center[0]*i,-e.center[1]*i,-e.center[2]*i),this.group.matrixWorldNeedsUpdate=!0;const r=new pt;r.setAttribute("position",new Be(e.vertices,3)),r.setIndex(new Be(e.faces,1)),r.computeVertexNormals(),r.setAttribute("skinIndex",new zo(e.skinJoints,4)),r.setAttribute("skinWeight",new Be(e.skinWeights,4));const s=a?$0(a):[];ol(r,s),this.lbsMaterial=new Jt({glslVersion:Ea,vertexShader:sl,fragmentShader:qo,uniforms:{baseColor:{value:new Ve().setHex(ec,kt)},deformedNormalWeight:{value:1},colorHarmonic:{value:-1},wire:{value:!1}},side:Kt}),this.skinned=new Sh(r,this.lbsMaterial),this.skinned.frustumCulled=!1,this.skeletonBones=Array.from({length:e.b},()=>{const f=new fd;return f.matrixAutoUpdate=!1,f.matrixWorldAutoUpdate=!1,f}),this.rest=Array.from({length:e.b},(f,b)=>new ze().fromArray(e.boneMatrices,16*b));const o=Array.from({length:e.b},(f,b)=>new ze().fromArray(e.bindMatrices,16*b));this.skinned.bindMode=zs;const c=new Vo(this.skeletonBones,o);if(this.skinned.bind(c,new ze),t){const f=t.drawnGeometry(e.vertices,{skinIndex:[e.skinJoints,4],skinWeight:[e.skinWeights,4]});ol(f,s.map(b=>t.gathered(b,3))),this.skinnedLook=new Sh(f,t.materialsWith(sl)),this.skinnedLook.frustumCulled=!1,this.skinnedLook.bindMode=zs,this.skinnedLook.bind(c,new ze);for(const b of this.skinnedLook.material)b.uniforms.deformedNormalWeight={value:1}}const l=new pt;l.setAttribute("position",new Be(new Float32Array(e.bodyEnds),3)),this.bones=new ky(l,new bd({color:8377343,depthTest:!1,transparent:!0,opacity:.9})),this.bones.renderOrder=2;const h=new pt;h.setAttribute("position",new Be(new Float32Array(e.jointPositions),3)),this.joints=new Mr(h,new vo({color:16777215,size:7,sizeAttenuation:!1,depthTest:!1})),this.joints.renderOrder=3;const d=new pt;d.setAttribute("position",new Be(new Float32Array(3),3)),this.picked=new Mr(d,new vo({color:16757575,size:13,sizeAttenuation:!1,depthTest:!1})),this.picked.renderOrder=4,this.group.add(this.skinned,this.bones,this.joints,this.picked),this.skinnedLook&&this.group.add(this.skinnedLook);for(const f of[this.skinned,this.bones,this.joints,this.picked])f.frustumCulled=!1;this.show({lbs:!1,bones:!1,joint:-1})}rig;group=new di;skinned;lbsMaterial;skinnedLook=null;bones;joints;picked;skeletonBones;rest;show(e){const t=!!(e.materials&&this.skinnedLook);if(this.skinned.visible=e.lbs&&!t,this.skinnedLook&&(this.skinnedLook.visible=e.lbs&&t),this.bones.visible=this.joints.visible=e.bones||e.joint>=0,this.picked.visible=e.joint>=0,e.joint>=0){const a=this.picked.geometry.getAttribute("position"),i=this.joints.geometry.getAttribute("position");a.setXYZ(0,i.getX(e.joint),i.getY(e.joint),i.getZ(e.joint)),a.needsUpdate=!0}}pose(e){const t=new ze,a=new ze,i=new O,r=this.bones.geometry.getAttribute("position");this.skeletonBones.forEach((o,c)=>{o.matrixWorld.fromArray(e,16*c),t.multiplyMatrices(o.matrixWorld,a.copy(this.rest[c]).invert());for(let l=0;l<2;l++)i.fromArray(this.rig.bodyEnds,6*c+3*l).applyMatrix4(t),r.setXYZ(2*c+l,i.x,i.y,i.z)}),r.needsUpdate=!0;const s=this.joints.geometry.getAttribute("position");for(let o=0;o<this.rig.j;o++){const c=this.rig.jointBodies[2*o];t.multiplyMatrices(this.skeletonBones[c].matrixWorld,a.copy(this.rest[c]).invert()),i.fromArray(this.rig.jointPositions,3*o).applyMatrix4(t),s.setXYZ(o,i.x,i.y,i.z)}s.needsUpdate=!0}ripple(e){for(const t of[this.skinned,this.skinnedLook]){const a=t?.morphTargetInfluences;if(a)for(let i=0;i<a.length;i++)a[i]=e?e[i]-1:0}}lbsPositions(){this.skinned.skeleton.update();const e=new Float32Array(3*this.rig.n),t=new O;for(let a=0;a<this.rig.n;a++)this.skinned.getVertexPosition(a,t).toArray(e,3*a);return e}nearestJoint(e,t,a,i=.06){const r=this.joints.geometry.getAttribute("position"),s=new O;let o=-1,c=i;for(let l=0;l<this.rig.j;l++){s.fromBufferAttribute(r,l).applyMatrix4(this.group.matrix).project(a);const h=Math.hypot(s.x-e,s.y-t);h<c&&(o=l,c=h)}return o}dispose(){if(this.group.removeFromParent(),this.skinned.geometry.dispose(),this.lbsMaterial.dispose(),this.skinnedLook){this.skinnedLook.geometry.dispose();for(const e of this.skinnedLook.material)e.dispose()}this.skinned.skeleton.dispose();for(const e of[this.bones,this.joints,this.picked])e.geometry.dispose(),e.material.dispose()}}const aw=.02,cl=new WeakMap;function Xd(n){let e=cl.get(n);if(e)return e;const{n:t,k:a,G:i}=n,r=[1/0,1/0,1/0],s=[-1/0,-1/0,-1/0];for(let f=0;f<t;f++)for(let b=0;b<3;b++)r[b]=Math.min(r[b],n.vertices[3*f+b]),s[b]=Math.max(s[b],n.vertices[3*f+b]);const o=r[1],c=aw*Math.hypot(s[0]-r[0],s[1]-r[1],s[2]-r[2]),l=new Float64Array(t),h=new Float32Array(t*a),d=new Float64Array(a).fill(1/0);for(let f=0;f<t;f++){l[f]=n.vertices[3*f+1]-o+c;for(let b=0;b<a;b++){const p=b>>2,g=b&3,m=Math.abs(n.tau[((f*i+p)*3+1)*4+g]);h[f*a+b]=m,m>0&&(d[b]=Math.min(d[b],l[f]/m))}}return e={room:l,sink:h,caps:d},cl.set(n,e),e}function nw(n,e){return Xd(n).caps[e]*n.reach[e]}function iw(n,e,t){if(!e.length)return t;const a=Xd(n),i=t.map((o,c)=>Math.sign(o)*Math.min(Math.abs(o),a.caps[e[c]]*n.reach[e[c]])),r=i.map((o,c)=>Math.abs(o)/n.reach[e[c]]);let s=0;for(let o=0;o<n.n;o++){let c=0;for(let l=0;l<e.length;l++)c+=a.sink[o*n.k+e[l]]*r[l];s=Math.max(s,c/a.room[o])}return s>1?i.map(o=>o/s):i}const hl=[.8,3.5],ll=40*Math.PI/180;function rw(n){const e=Array.from(n).filter(i=>i>0);if(!e.length)return 1;const t=hl[0]/Math.min(...e),a=hl[1]/Math.max(...e);return t<=a?Math.min(Math.max(1,t),a):Math.sqrt(t*a)}function sw(n,e){const t=e.map(r=>n.amplitudes[r]);let a=0;for(let r=0;r<n.j;r++){let s=0;e.forEach((o,c)=>{s+=n.jointBend[r*n.k+o]*(t[c]/n.reach[o])}),a=Math.max(a,s)}const i=a>ll?ll/a:1;return t.map(r=>r*i)}function Eo(n,e){const t=e?.selected??n.palette.selected;for(const c of t)if(!(Number.isInteger(c)&&c>=0&&c<n.k))throw new Error(`the mapping selects mode ${c}; the rig has ${n.k}`);const a=t.map((c,l)=>l).sort((c,l)=>t[c]-t[l]),i=a.map(c=>t[c]),r=iw(n,i,e?.amplitudes?a.map(c=>e.amplitudes[c]):sw(n,i)),s=e?.phases?a.map(c=>e.phases[c]):i.map(c=>n.phases[c]),o=e?.time_scale??rw(i.map(c=>n.frequencies[c]));return{selected:i,amplitudes:r,phases:s,time_scale:o,tempo:e?.tempo??null}}function ow(n,e,t){let a=.5,i=1/0;for(const r of[.5,1,2]){const s=Math.abs(Math.log(Math.max(n*e,1e-12)/(r*t/60)));s<i&&(a=r,i=s)}return a}function cw(n){const e=(n-Math.PI/2)/Math.PI;let t=Math.round(e);return Math.abs(e%1)===.5&&t%2!==0&&(t-=1),Math.PI/2+Math.PI*t}function Kd(n,e,t=!0){const a=Eo(n,e.modes),i=Int32Array.from(a.selected);return{...Ir(e,i.length),selected:i,amplitudes:Float64Array.from(a.amplitudes),phases:Float64Array.from(a.phases),timeScale:a.time_scale,offset:e.offset??0,music:t,tempo:a.tempo??null,lock:!0}}function hw(n,e,t){return{...Ir({transfer:[],amplification:[0]},1),gain:0,selected:Int32Array.of(e),amplitudes:Float64Array.of(n.tileAmplitudes[e]),phases:Float64Array.of(n.phases[e]),timeScale:t,offset:0,music:!1,tempo:"free",lock:!1}}function lw(n,e,t=0,a=n.gain){if(!n.music||e===null)return new Float64Array(n.k).fill(1);const i=Ko(n,e,a,void 0,t);for(let r=0;r<i.length;r++)i[r]+=n.offset-1;return i}function dw(n,e,t,a,i,r){const s=i??new Float64Array(n.k);return s.fill(0),e.selected.forEach((o,c)=>{const l=e.amplitudes[c]/n.reach[o],h=r?2*Math.PI*ow(n.frequencies[o],e.timeScale,r.tempo)*r.phase+cw(e.phases[c]):2*Math.PI*n.frequencies[o]*e.timeScale*a+e.phases[c];s[o]=t[c]*l*Math.sin(h)*(r?.accent??1)}),s}function br(n,e,t){const a=t??new Float32Array(36*n.G);a.fill(0);const i=ki(n);for(let r=0;r<n.G;r++)for(let s=0;s<3;s++){const o=4*(3*(3*r+s)+s);for(let c=0;c<4&&4*r+c<n.k;c++)a[o+c]=e[4*r+c]*i}return a}function fw(n,e,t,a=new Float64Array(9)){const i=Math.hypot(n,e,t),r=i<1e-12?1:Math.sin(i)/i,s=i<1e-6?.5:(1-Math.cos(i))/(i*i);return a[0]=1-s*(e*e+t*t),a[1]=-r*t+s*n*e,a[2]=r*e+s*n*t,a[3]=r*t+s*n*e,a[4]=1-s*(n*n+t*t),a[5]=-r*n+s*e*t,a[6]=-r*e+s*n*t,a[7]=r*n+s*e*t,a[8]=1-s*(n*n+e*e),a}function uw(n,e,t){const a=t??new Float32Array(16*n.b),i=new Float64Array(6),r=new Float64Array(9);for(let s=0;s<n.b;s++){i.fill(0);for(let l=0;l<n.k;l++){if(e[l]===0)continue;const h=6*(l*n.b+s);for(let d=0;d<6;d++)i[d]+=e[l]*n.bodyTwists[h+d]}fw(i[0],i[1],i[2],r);const o=n.bodyRotations.subarray(9*s,9*s+9),c=a.subarray(16*s,16*s+16);for(let l=0;l<3;l++){for(let h=0;h<3;h++)c[4*h+l]=o[3*l]*r[h]+o[3*l+1]*r[3+h]+o[3*l+2]*r[6+h];c[12+l]=n.bodyCenters[3*s+l]+o[3*l]*i[3]+o[3*l+1]*i[4]+o[3*l+2]*i[5],c[3+4*l]=0}c[15]=1}return a}class bw{constructor(e){this.music=e}music;rig=null;surface=null;surfaceOf=()=>null;coefficientsBuffer=new Float64Array(0);get ready(){return this.rig!==null}coefficients(e,t){const a=this.rig;return this.coefficientsBuffer.length!==a.k&&(this.coefficientsBuffer=new Float64Array(a.k)),dw(a,e,this.drive(e,t),t,this.coefficientsBuffer,this.beat(e,t))}beat(e,t){const a=this.music.spectrum;if(!(!e.lock||e.tempo==="free"||!a||!Tr(a)))return Il(a,t)}drive(e,t){const a=e.music&&this.music.spectrum,i=a?this.music.bandValuesAt(t,e):null;return lw(e,i,a?this.music.kick(e,t):0,e.gain*(a?this.music.sectionGain(e,t):1))}weights(e,t){const a=this.coefficients(e,t);if(!this.surface)return br(this.rig,a);const i=br(this.rig,a,new Float32Array(12*this.texels())),r=this.surfaceOf(e);return r?Q0(this.rig,r.surface,r.phi(this.music,t),i):i}texels(){return 3*this.rig.G+(this.surface?.surface.G??0)}loudestTimes(e){return this.music.spectrum?this.music.loudestTimes(e):[]}framingWeights(e){const t=e,a=this.rig,i=new Float64Array(t.k).fill(t.music?Math.abs(t.offset):1);if(t.music)for(const l of this.loudestTimes(6))this.drive(t,l).forEach((h,d)=>{i[d]=Math.max(i[d],Math.abs(h))});const r=[],s=new Float64Array(a.k),o=(l,h)=>{s.fill(0);for(const d of l)s[t.selected[d]]=h*i[d]*t.amplitudes[d]/a.reach[t.selected[d]];r.push(br(a,s,new Float32Array(12*this.texels())))},c=[...t.selected.keys()];for(const l of[1,-1])c.forEach(h=>o([h],l)),c.length>1&&o(c,l);return r}}function mw(n,e){const t=gd(e).map(a=>e.selected[a]);return t.length===1?`${il(t)} · ${wi(n.frequencies[t[0]],e.timeScale)}`:`${il(t)} · ×${e.timeScale.toFixed(2)} time scale`}const Oa={shading:"smooth",deformedNormalWeight:1,materials:!0};class pw{constructor(e){this.events=e,I("rig-show-modes").addEventListener("click",()=>this.setMode("modes")),I("rig-show-dances").addEventListener("click",()=>this.setMode("dances")),I("rig-prev-modes").addEventListener("click",()=>this.setPage(this.page-1)),I("rig-more-modes").addEventListener("click",()=>this.setPage(this.page+1)),I("rig-combine").addEventListener("click",()=>{this.events.combine([...this.selectedModes].sort((t,a)=>t-a))}),I("rig-breed").addEventListener("click",()=>{this.events.guard("Breeding failed",()=>this.breed())}),I("rig-generation").addEventListener("change",t=>{this.showGeneration(Number(t.target.value))})}events;mode="modes";pageSize=16;page=0;generations=[];generation=-1;rig=null;prepared=[];tiles=[];selectedModes=new Set;selectedDances=new Set;surfaces=null;shape=null;closeUps=new Map;get pages(){return this.rig?Math.max(1,Math.ceil(this.rig.k/this.pageSize)):1}get modes(){if(!this.rig)return[];const e=this.page*this.pageSize;return Array.from({length:Math.max(0,Math.min(this.pageSize,this.rig.k-e))},(t,a)=>e+a)}get selection(){return[...this.mode==="modes"?this.selectedModes:this.selectedDances].sort((t,a)=>t-a)}dances(){return this.generations[this.generation]??[]}dance(e){const{surface:t,...a}=this.dances()[e],i=this.surfaces;return i?.length?{...a,surface:t??i[e%i.length]}:a}setSurfaces(e){this.surfaces=e,this.mode==="dances"&&this.build()}surfaceGenes(e){const t=this.mode==="dances"?this.prepared.indexOf(e):-1;return t<0?null:this.dance(t).surface??null}shots(){return this.tiles.map((e,t)=>({element:e.view,prepared:this.prepared[t],look:Oa,closeUp:e.closeUp}))}views(){return this.tiles.map(e=>e.view)}labels(){return this.tiles.map(e=>e.label.textContent??"")}closeUpsShown(){return this.tiles.map(({closeUp:e})=>e?{corner:e.closeUp.corner,count:e.closeUp.count,share:e.closeUp.share,box:e.closeUp.box,turn:e.closeUp.turn,tag:e.element.textContent??""}:null)}setRig(e,t){this.rig=e,this.closeUps.clear(),t&&(this.page=0,this.selectedModes.clear(),this.selectedDances.clear(),this.generations=[],this.generation=-1);for(const a of this.selectedModes)a>=e.k&&this.selectedModes.delete(a);this.setPage(Math.min(this.page,this.pages-1))}setDances(e){this.generations=[e],this.showGeneration(0)}setMode(e){this.mode=e,I("rig-show-modes").classList.toggle("active",e==="modes"),I("rig-show-dances").classList.toggle("active",e==="dances"),I("rig-modes-controls").hidden=e!=="modes",I("rig-dances-controls").hidden=e!=="dances",this.build()}setPage(e){this.page=Math.max(0,Math.min(e,this.pages-1)),this.mode==="modes"&&this.build()}showGeneration(e,t=[]){this.generation=Math.max(0,Math.min(e,this.generations.length-1)),this.selectedDances.clear();for(const i of t)i<this.dances().length&&this.selectedDances.add(i);const a=I("rig-generation");a.innerHTML="",this.generations.forEach((i,r)=>a.add(new Option(`generation ${r+1}`,String(r),!1,r===this.generation))),this.mode==="dances"&&this.build(),this.events.changed?.()}restoreDances(e,t,a){e.length&&(this.generations=e,this.showGeneration(t,a))}get selectedDanceList(){return[...this.selectedDances].sort((e,t)=>e-t)}layout(){const e=I("rig-tiles"),t=e.getBoundingClientRect();e.style.setProperty("--columns",String(Qf(this.tiles.length||this.prepared.length,t.width-20,t.height-10,this.aspect,6)))}get aspect(){if(!this.rig)return 1;if(this.shape?.rig!==this.rig){const{x:e,y:t}=nn(this.rig.vertices,Xt),a=i=>i.reduce((r,s)=>Math.max(r,s),-1/0)-i.reduce((r,s)=>Math.min(r,s),1/0);this.shape={rig:this.rig,aspect:a(e)/Math.max(a(t),1e-9)}}return this.shape.aspect}refresh(){this.build()}toggle(e){const t=this.mode==="modes"?this.selectedModes:this.selectedDances,a=this.mode==="modes"?this.modes[e]:e;a!==void 0&&(t.has(a)?t.delete(a):t.add(a),this.tiles[e]?.element.classList.toggle("selected",t.has(a)),this.updateButtons(),this.mode==="dances"&&this.events.changed?.())}async breed(e=Math.floor(Math.random()*2**31)){const t=[...this.selectedDances].sort((i,r)=>i-r).map(i=>this.dance(i));if(!t.length)return;this.events.status("breeding…");const a=await xl(t,this.dances().length,e,{rig:this.rig.id,song:this.events.songId()});this.generations.push(a),this.showGeneration(this.generations.length-1),this.events.status("")}updateButtons(){const e=I("rig-combine");e.disabled=this.selectedModes.size===0,e.textContent=this.selectedModes.size?`combine ${this.selectedModes.size} selected`:"combine selected";const t=I("rig-breed");t.disabled=this.selectedDances.size===0,t.textContent=this.selectedDances.size?`breed ${this.selectedDances.size} selected`:"breed selected",I("rig-prev-modes").disabled=this.page===0,I("rig-more-modes").disabled=this.page>=this.pages-1;const a=this.modes;I("rig-modes-page").textContent=this.rig&&a.length?`modes ${a[0]+1}–${a[a.length-1]+1} of ${this.rig.k}`:""}build(){const e=this.rig,t=I("rig-tiles");if(t.innerHTML="",this.tiles=[],this.prepared=[],e){const a=this.events.timeScale();this.mode==="modes"?this.prepared=this.modes.map(i=>hw(e,i,nl(e.frequencies[i],a).timeScale)):this.prepared=this.dances().map(i=>Kd(e,i)),this.layout(),this.tiles=this.prepared.map((i,r)=>{const s=this.makeTile(r,i);return t.appendChild(s.element),s})}this.updateButtons(),this.events.requestDraw()}makeTile(e,t){const a=this.rig,i=document.createElement("div");i.className="rig-tile",i.innerHTML='<div class="view"></div><div class="caption"></div>';const r=i.querySelector(".caption");if(this.mode==="modes"){const c=t.selected[0],l=a.frequencies[c];r.textContent=`mode ${c+1} · ${nl(l,this.events.timeScale()).label}`,r.title=`natural frequency ${l.toFixed(3)} Hz, shown × ${t.timeScale.toFixed(3)} (a page shows ${Er.low}–${Er.high} Hz); the player plays it at the palette's time scale; click to select, then combine`,i.classList.toggle("selected",this.selectedModes.has(c))}else{r.textContent=`#${e+1} · ${mw(a,t)}`+(this.dance(e).surface?" · rippling skin":""),r.title="the modes this dance's mapping drives (a band reaches them with a non-zero amplification), at its time scale",i.classList.toggle("selected",this.selectedDances.has(e));const c=document.createElement("div");c.className="actions",c.innerHTML=`<button class="open" title="play this dance in the player">open</button>
        <button class="save" title="download this mapping (JSON)">save</button>`,i.appendChild(c)}i.addEventListener("click",c=>{const l=c.target,h=this.dance(e);if(l.closest(".open")){this.events.open(h,`dance ${e+1}`);return}if(l.closest(".save")){Ei(h,Wa(a.name,`g${this.generation+1}-${e+1}`,"json"));return}this.toggle(e)});const s=i.querySelector(".view"),o=this.mode==="modes"?this.closeUpOf(t):null;return{element:i,view:s,label:r,closeUp:o?gw(s,o):void 0}}closeUpOf(e){const t=e.selected[0];return this.closeUps.has(t)||this.closeUps.set(t,this.events.closeUp?.(e)??null),this.closeUps.get(t)}}function gw(n,e){const t=document.createElement("div");t.className=`close-up ${e.corner}`;const a=["","side","behind","side"][e.turn];return t.title=`close-up of the part this mode moves (it spans ${Math.round(100*e.share)}% of the model): the same skin, seen nearer`+(a?`, from ${a==="side"?"the side":"the far side"} (where its motion shows), cut away before it`:""),t.innerHTML=`<span class="tag">close-up${a?`: ${a}`:""}</span>`,n.appendChild(t),{element:t,closeUp:e}}const ii=Math.PI/180;class vw{constructor(e){this.events=e;const t=(a,i,r)=>{const s=I(a);s.addEventListener("input",()=>{I(`${a}-out`).textContent=i(Number(s.value)),r(Number(s.value))})};t("rig-scale",a=>`${a.toFixed(2)}×`,a=>{this.palette&&(this.palette.time_scale=a,this.buildPalette(),this.update(),this.events.timeScaleChanged())}),t("rig-gain",a=>`${a.toFixed(2)}×`,a=>{this.mapping&&(this.mapping.gain=a,this.update())}),t("rig-offset",a=>a.toFixed(2),a=>{this.mapping&&(this.mapping.offset=a,this.update())}),I("rig-beat").addEventListener("change",a=>{this.palette&&(this.palette.tempo=a.target.checked?"beat":"free",this.update())}),I("rig-music").addEventListener("change",a=>{this.music=a.target.checked,this.update()}),I("rig-skinning").addEventListener("change",a=>{this.skinning=a.target.value,this.events.requestDraw()}),I("rig-materials").addEventListener("change",a=>{Oa.materials=a.target.checked,this.events.requestDraw()}),I("rig-bones").addEventListener("change",a=>{this.bones=a.target.checked,this.events.requestDraw()}),I("rig-joint").addEventListener("change",a=>{this.pick(Number(a.target.value))}),["x","y","z"].forEach((a,i)=>{const r=I(`rig-turn-${a}`);r.addEventListener("input",()=>{I(`rig-turn-${a}-out`).textContent=`${r.value}°`}),r.addEventListener("change",()=>{const s=Number(r.value),o=s-this.turned[i];if(this.joint<0||o===0)return;const c=[0,0,0];c[i]=o*ii,this.events.guard("Could not turn the joint",async()=>{await this.events.pose(this.joint,c),this.turned[i]=s}).then(()=>{r.value=String(this.turned[i]),I(`rig-turn-${a}-out`).textContent=`${this.turned[i]}°`})})}),I("rig-reset").addEventListener("click",()=>{this.events.guard("Could not reset the rig",()=>this.events.reset())}),I("rig-stiffness-set").addEventListener("click",()=>{const a=Number(I("rig-stiffness").value);this.joint<0||this.events.guard("Could not set the stiffness",()=>this.events.stiffness(this.joint,a))}),I("rig-stiffness-auto").addEventListener("click",()=>{this.joint<0||this.events.guard("Could not set the stiffness",()=>this.events.stiffness(this.joint,"auto"))}),I("rig-save").addEventListener("click",()=>{const a=this.saved();a&&Ei(a,Wa(this.rig?.name??"",this.source,"json"))})}events;mapping=null;palette=null;prepared=null;source="";music=!0;skinning="modal";bones=!1;joint=-1;rig=null;turned=[0,0,0];saved(){if(!this.mapping||!this.palette)return null;const e={...this.mapping,version:3,gain:this.music?this.mapping.gain??1:0,smoothing:this.mapping.smoothing??0,offset:this.music?this.mapping.offset??0:1,modes:{...this.palette},look:{...this.mapping.look,materials:Oa.materials}},{surface:t,...a}=e,i=this.events.surface?.()??null;return i?{...a,surface:i}:a}shot(e){return this.prepared?{element:e,prepared:this.prepared,look:Oa,source:this.mapping??void 0}:null}show(e,t){this.mapping=structuredClone(e),Oa.materials=e.look?.materials??!0,I("rig-materials").checked=Oa.materials,this.source=t,this.palette=this.rig?Eo(this.rig,e.modes):null,this.buildPalette(),this.refreshInfo(),this.update()}setRig(e,t){this.rig=e,t&&(this.mapping=null,this.palette=null,this.prepared=null,this.joint=-1),this.palette&&this.palette.selected.some(i=>i>=e.k)&&(this.palette=null),this.mapping&&!this.palette&&(this.palette=Eo(e,null));const a=I("rig-joint");a.innerHTML="",a.add(new Option("— pick a joint —","-1")),e.jointList.forEach((i,r)=>a.add(new Option(`${i.name} (${i.type}${i.closes_loop?", in a loop":""})`,String(r)))),this.pick(this.joint<e.j?this.joint:-1,!t),this.buildPalette(),this.update(),this.refreshInfo()}refreshInfo(){const e=this.rig;if(!e)return;const t=this.palette?.time_scale??e.palette?.time_scale??1,a=(i,r,s)=>`${i} ${i===1?r:s}`;I("rig-info").textContent=`${e.name}: ${a(e.b,"body","bodies")}, ${a(e.j,"joint","joints")}, ${a(e.k,"mode","modes")}, ${a(e.n,"vertex","vertices")} · lowest mode ${e.k?wi(e.frequencies[0],t):"–"}`+(e.edited?" · pose or stiffness edited (kept by the server until reset pose)":"")}pick(e,t=!1){const a=this.rig;if(!a)return;(e!==this.joint||!t)&&(this.turned=[0,0,0]),this.joint=e,I("rig-joint").value=String(e);const i=e>=0?a.jointList[e]:null;["x","y","z"].forEach((s,o)=>{const c=I(`rig-turn-${s}`);c.value=String(this.turned[o]),c.disabled=!i||i.closes_loop,I(`rig-turn-${s}-out`).textContent=`${this.turned[o]}°`}),i?.closes_loop?I("rig-joint").title=`${i.name} closes a loop: it cannot turn one side alone (its stiffness can change)`:I("rig-joint").removeAttribute("title");const r=I("rig-stiffness");r.disabled=!i,r.value=i?.stiffness.length?String(+i.stiffness[0].toPrecision(4)):"",I("rig-stiffness-default").textContent=i?.default_stiffness.length?`default ${i.default_stiffness.map(s=>+s.toPrecision(3)).join(", ")}`:"",this.events.requestDraw()}update(){if(this.rig&&this.mapping&&this.palette){this.prepared=Kd(this.rig,{...this.mapping,modes:this.palette},this.music);const e=this.palette.amplitudes,t=this.prepared.amplitudes,a=e.some(i=>i>0)?Math.max(...t.map((i,r)=>Math.abs(e[r])>0?Math.abs(i/e[r]):0)):1;I("rig-floor-note").hidden=a>.999,I("rig-floor-note").textContent=`together these amplitudes would sink a limb below the floor: they play at ×${a.toFixed(2)}`}this.events.changed?.(),this.events.requestDraw()}buildPalette(){const e=this.rig,t=this.palette,a=this.mapping;I("rig-source").textContent=this.source;const i=I("rig-palette");if(i.innerHTML="",!e||!t||!a)return;const r=(s,o,c)=>{I(s).value=String(o),I(`${s}-out`).textContent=c};r("rig-scale",t.time_scale,`${t.time_scale.toFixed(2)}×`),I("rig-beat").checked=t.tempo!=="free",r("rig-gain",a.gain??1,`${(a.gain??1).toFixed(2)}×`),r("rig-offset",a.offset??0,(a.offset??0).toFixed(2)),t.selected.forEach((s,o)=>{const c=document.createElement("div");c.className="rig-mode-row";const l=t.amplitudes[o]/ii,h=t.phases[o]/ii,d=Math.min(Math.max(90,Math.ceil(2*l)),Math.floor(2*nw(e,s)/ii)/2);c.innerHTML=`<span class="name" title="as played: natural frequency ${e.frequencies[s].toFixed(3)} Hz × the time scale">mode ${s+1} · ${wi(e.frequencies[s],t.time_scale)}</span>
        <label title="reach at φ = 1: the largest body rotation, degrees (at most ${d}°: beyond, the skin would sink below the floor)">amplitude
        <input type="range" class="amplitude" min="0" max="${d}" step="0.5" value="${l}">
        <output>${l.toFixed(1)}°</output></label>
        <label title="phase γ, degrees">phase <input type="range" class="phase" min="0"
        max="360" step="1" value="${h%360}"><output>${(h%360).toFixed(0)}°</output></label>`;const f=(b,p,g,m)=>{const u=c.querySelector(b);u.addEventListener("input",()=>{p[o]=Number(u.value)*ii,u.nextElementSibling.textContent=`${Number(u.value).toFixed(m)}${g}`,this.update()})};f(".amplitude",t.amplitudes,"°",1),f(".phase",t.phases,"°",0),i.appendChild(c)})}}class yw{saved=new Map;restore(e){for(const[t,a]of Object.entries(e))this.saved.set(t,a)}get(e){return this.saved.get(e)}forget(e){this.saved.delete(e)}set(e,t){this.saved.set(e,structuredClone(t)),Gn({rigs:this.snapshot()})}snapshot(){return Object.fromEntries(this.saved)}}const xw=150;class ww{constructor(e){this.events=e;const t=I("rig-surface");t.addEventListener("change",()=>{this.events.guard("Could not ripple the skin",()=>this.switchTo(t.checked))}),I("rig-surface-dance").addEventListener("change",()=>this.choose());const a=I("rig-surface-gain");a.addEventListener("input",()=>{I("rig-surface-gain-out").textContent=`${Number(a.value).toFixed(2)}×`,this.current&&(this.current.gain=Number(a.value)),this.refreshShare()})}events;surface=null;dances=[];menu=[];song="";current=null;pending;get genes(){return this.current?.genes()??null}reset(){this.surface=null,this.current=null,this.dances=this.menu=[],this.events.dances(null),I("rig-surface").checked=!1,this.enable(!1),I("rig-surface-share").textContent=""}async songChanged(){this.current&&await this.switchTo(!0)}async switchTo(e){const t=this.events.rig();if(!e||!t){this.current=null,this.enable(!1),this.events.play(null),this.events.dances(null),this.showShare();return}this.surface??=await J0(t.id),(this.song!==this.events.songId()||!this.dances.length)&&(this.song=this.events.songId(),this.dances=await Y0(t.id,this.song),this.menu=[...this.dances],I("rig-surface-dance").replaceChildren(...this.dances.map((i,r)=>new Option(`dance ${r+1}`,String(r))))),this.enable(!0),this.choose(),this.events.dances(this.dances)}async follow(e){e!==null!=(this.current!==null)&&(I("rig-surface").checked=e!==null,await this.switchTo(e!==null)),e&&this.playGenes(e)}playGenes(e){if(!this.current)return;let t=this.menu.indexOf(e);t<0&&(t=this.menu.push(e)-1,I("rig-surface-dance").add(new Option(`a dance's own ${t-this.dances.length+1}`,String(t)))),I("rig-surface-dance").value=String(t),this.choose()}choose(){if(!this.surface||!this.menu.length)return;const e=Number(I("rig-surface-dance").value)||0;this.current=new qd(this.surface,this.menu[e],Number(I("rig-surface-gain").value)),this.events.play(this.current),this.showShare()}refreshShare(){this.current&&(clearTimeout(this.pending),this.pending=setTimeout(()=>this.showShare(),xw))}showShare(){const e=this.current?this.events.share():null;I("rig-surface-share").textContent=e===null?"":`${Math.round(100*e)}% of the motion`}enable(e){I("rig-surface-dance").disabled=!e,I("rig-surface-gain").disabled=!e}}const dl={type:"change"},tc={type:"start"},Jd={type:"end"},nr=new Ai,fl=new ja,Mw=Math.cos(70*Kl.DEG2RAD),lt=new O,It=2*Math.PI,tt={NONE:-1,ROTATE:0,DOLLY:1,PAN:2,TOUCH_ROTATE:3,TOUCH_PAN:4,TOUCH_DOLLY_PAN:5,TOUCH_DOLLY_ROTATE:6},Es=1e-6;class _w extends Ry{constructor(e,t=null){super(e,t),this.state=tt.NONE,this.enabled=!0,this.target=new O,this.cursor=new O,this.minDistance=0,this.maxDistance=1/0,this.minZoom=0,this.maxZoom=1/0,this.minTargetRadius=0,this.maxTargetRadius=1/0,this.minPolarAngle=0,this.maxPolarAngle=Math.PI,this.minAzimuthAngle=-1/0,this.maxAzimuthAngle=1/0,this.enableDamping=!1,this.dampingFactor=.05,this.enableZoom=!0,this.zoomSpeed=1,this.enableRotate=!0,this.rotateSpeed=1,this.enablePan=!0,this.panSpeed=1,this.screenSpacePanning=!0,this.keyPanSpeed=7,this.zoomToCursor=!1,this.autoRotate=!1,this.autoRotateSpeed=2,this.keys={LEFT:"ArrowLeft",UP:"ArrowUp",RIGHT:"ArrowRight",BOTTOM:"ArrowDown"},this.mouseButtons={LEFT:In.ROTATE,MIDDLE:In.DOLLY,RIGHT:In.PAN},this.touches={ONE:kn.ROTATE,TWO:kn.DOLLY_PAN},this.target0=this.target.clone(),this.position0=this.object.position.clone(),this.zoom0=this.object.zoom,this._domElementKeyEvents=null,this._lastPosition=new O,this._lastQuaternion=new on,this._lastTargetPosition=new O,this._quat=new on().setFromUnitVectors(e.up,new O(0,1,0)),this._quatInverse=this._quat.clone().invert(),this._spherical=new Dh,this._sphericalDelta=new Dh,this._scale=1,this._panOffset=new O,this._rotateStart=new De,this._rotateEnd=new De,this._rotateDelta=new De,this._panStart=new De,this._panEnd=new De,this._panDelta=new De,this._dollyStart=new De,this._dollyEnd=new De,this._dollyDelta=new De,this._dollyDirection=new O,this._mouse=new De,this._performCursorZoom=!1,this._pointers=[],this._pointerPositions={},this._controlActive=!1,this._onPointerMove=Sw.bind(this),this._onPointerDown=Ew.bind(this),this._onPointerUp=Aw.bind(this),this._onContextMenu=Dw.bind(this),this._onMouseWheel=Rw.bind(this),this._onKeyDown=Cw.bind(this),this._onTouchStart=Iw.bind(this),this._onTouchMove=Pw.bind(this),this._onMouseDown=Tw.bind(this),this._onMouseMove=kw.bind(this),this._interceptControlDown=Nw.bind(this),this._interceptControlUp=Uw.bind(this),this.domElement!==null&&this.connect(),this.update()}connect(){this.domElement.addEventListener("pointerdown",this._onPointerDown),this.domElement.addEventListener("pointercancel",this._onPointerUp),this.domElement.addEventListener("contextmenu",this._onContextMenu),this.domElement.addEventListener("wheel",this._onMouseWheel,{passive:!1}),this.domElement.getRootNode().addEventListener("keydown",this._interceptControlDown,{passive:!0,capture:!0}),this.domElement.style.touchAction="none"}disconnect(){this.domElement.removeEventListener("pointerdown",this._onPointerDown),this.domElement.removeEventListener("pointermove",this._onPointerMove),this.domElement.removeEventListener("pointerup",this._onPointerUp),this.domElement.removeEventListener("pointercancel",this._onPointerUp),this.domElement.removeEventListener("wheel",this._onMouseWheel),this.domElement.removeEventListener("contextmenu",this._onContextMenu),this.stopListenToKeyEvents(),this.domElement.getRootNode().removeEventListener("keydown",this._interceptControlDown,{capture:!0}),this.domElement.style.touchAction="auto"}dispose(){this.disconnect()}getPolarAngle(){return this._spherical.phi}getAzimuthalAngle(){return this._spherical.theta}getDistance(){return this.object.position.distanceTo(this.target)}listenToKeyEvents(e){e.addEventListener("keydown",this._onKeyDown),this._domElementKeyEvents=e}stopListenToKeyEvents(){this._domElementKeyEvents!==null&&(this._domElementKeyEvents.removeEventListener("keydown",this._onKeyDown),this._domElementKeyEvents=null)}saveState(){this.target0.copy(this.target),this.position0.copy(this.object.position),this.zoom0=this.object.zoom}reset(){this.target.copy(this.target0),this.object.position.copy(this.position0),this.object.zoom=this.zoom0,this.object.updateProjectionMatrix(),this.dispatchEvent(dl),this.update(),this.state=tt.NONE}update(e=null){const t=this.object.position;lt.copy(t).sub(this.target),lt.applyQuaternion(this._quat),this._spherical.setFromVector3(lt),this.autoRotate&&this.state===tt.NONE&&this._rotateLeft(this._getAutoRotationAngle(e)),this.enableDamping?(this._spherical.theta+=this._sphericalDelta.theta*this.dampingFactor,this._spherical.phi+=this._sphericalDelta.phi*this.dampingFactor):(this._spherical.theta+=this._sphericalDelta.theta,this._spherical.phi+=this._sphericalDelta.phi);let a=this.minAzimuthAngle,i=this.maxAzimuthAngle;isFinite(a)&&isFinite(i)&&(a<-Math.PI?a+=It:a>Math.PI&&(a-=It),i<-Math.PI?i+=It:i>Math.PI&&(i-=It),a<=i?this._spherical.theta=Math.max(a,Math.min(i,this._spherical.theta)):this._spherical.theta=this._spherical.theta>(a+i)/2?Math.max(a,this._spherical.theta):Math.min(i,this._spherical.theta)),this._spherical.phi=Math.max(this.minPolarAngle,Math.min(this.maxPolarAngle,this._spherical.phi)),this._spherical.makeSafe(),this.enableDamping===!0?this.target.addScaledVector(this._panOffset,this.dampingFactor):this.target.add(this._panOffset),this.target.sub(this.cursor),this.target.clampLength(this.minTargetRadius,this.maxTargetRadius),this.target.add(this.cursor);let r=!1;if(this.zoomToCursor&&this._performCursorZoom||this.object.isOrthographicCamera)this._spherical.radius=this._clampDistance(this._spherical.radius);else{const s=this._spherical.radius;this._spherical.radius=this._clampDistance(this._spherical.radius*this._scale),r=s!=this._spherical.radius}if(lt.setFromSpherical(this._spherical),lt.applyQuaternion(this._quatInverse),t.copy(this.target).add(lt),this.object.lookAt(this.target),this.enableDamping===!0?(this._sphericalDelta.theta*=1-this.dampingFactor,this._sphericalDelta.phi*=1-this.dampingFactor,this._panOffset.multiplyScalar(1-this.dampingFactor)):(this._sphericalDelta.set(0,0,0),this._panOffset.set(0,0,0)),this.zoomToCursor&&this._performCursorZoom){let s=null;if(this.object.isPerspectiveCamera){const o=lt.length();s=this._clampDistance(o*this._scale);const c=o-s;this.object.position.addScaledVector(this._dollyDirection,c),this.object.updateMatrixWorld(),r=!!c}else if(this.object.isOrthographicCamera){const o=new O(this._mouse.x,this._mouse.y,0);o.unproject(this.object);const c=this.object.zoom;this.object.zoom=Math.max(this.minZoom,Math.min(this.maxZoom,this.object.zoom/this._scale)),this.object.updateProjectionMatrix(),r=c!==this.object.zoom;const l=new O(this._mouse.x,this._mouse.y,0);l.unproject(this.object),this.object.position.sub(l).add(o),this.object.updateMatrixWorld(),s=lt.length()}else console.warn("WARNING: OrbitControls.js encountered an unknown camera type - zoom to cursor disabled."),this.zoomToCursor=!1;s!==null&&(this.screenSpacePanning?this.target.set(0,0,-1).transformDirection(this.object.matrix).multiplyScalar(s).add(this.object.position):(nr.origin.copy(this.object.position),nr.direction.set(0,0,-1).transformDirection(this.object.matrix),Math.abs(this.object.up.dot(nr.direction))<Mw?this.object.lookAt(this.target):(fl.setFromNormalAndCoplanarPoint(this.object.up,this.target),nr.intersectPlane(fl,this.target))))}else if(this.object.isOrthographicCamera){const s=this.object.zoom;this.object.zoom=Math.max(this.minZoom,Math.min(this.maxZoom,this.object.zoom/this._scale)),s!==this.object.zoom&&(this.object.updateProjectionMatrix(),r=!0)}return this._scale=1,this._performCursorZoom=!1,r||this._lastPosition.distanceToSquared(this.object.position)>Es||8*(1-this._lastQuaternion.dot(this.object.quaternion))>Es||this._lastTargetPosition.distanceToSquared(this.target)>Es?(this.dispatchEvent(dl),this._lastPosition.copy(this.object.position),this._lastQuaternion.copy(this.object.quaternion),this._lastTargetPosition.copy(this.target),!0):!1}_getAutoRotationAngle(e){return e!==null?It/60*this.autoRotateSpeed*e:It/60/60*this.autoRotateSpeed}_getZoomScale(e){const t=Math.abs(e*.01);return Math.pow(.95,this.zoomSpeed*t)}_rotateLeft(e){this._sphericalDelta.theta-=e}_rotateUp(e){this._sphericalDelta.phi-=e}_panLeft(e,t){lt.setFromMatrixColumn(t,0),lt.multiplyScalar(-e),this._panOffset.add(lt)}_panUp(e,t){this.screenSpacePanning===!0?lt.setFromMatrixColumn(t,1):(lt.setFromMatrixColumn(t,0),lt.crossVectors(this.object.up,lt)),lt.multiplyScalar(e),this._panOffset.add(lt)}_pan(e,t){const a=this.domElement;if(this.object.isPerspectiveCamera){const i=this.object.position;lt.copy(i).sub(this.target);let r=lt.length();r*=Math.tan(this.object.fov/2*Math.PI/180),this._panLeft(2*e*r/a.clientHeight,this.object.matrix),this._panUp(2*t*r/a.clientHeight,this.object.matrix)}else this.object.isOrthographicCamera?(this._panLeft(e*(this.object.right-this.object.left)/this.object.zoom/a.clientWidth,this.object.matrix),this._panUp(t*(this.object.top-this.object.bottom)/this.object.zoom/a.clientHeight,this.object.matrix)):(console.warn("WARNING: OrbitControls.js encountered an unknown camera type - pan disabled."),this.enablePan=!1)}_dollyOut(e){this.object.isPerspectiveCamera||this.object.isOrthographicCamera?this._scale/=e:(console.warn("WARNING: OrbitControls.js encountered an unknown camera type - dolly/zoom disabled."),this.enableZoom=!1)}_dollyIn(e){this.object.isPerspectiveCamera||this.object.isOrthographicCamera?this._scale*=e:(console.warn("WARNING: OrbitControls.js encountered an unknown camera type - dolly/zoom disabled."),this.enableZoom=!1)}_updateZoomParameters(e,t){if(!this.zoomToCursor)return;this._performCursorZoom=!0;const a=this.domElement.getBoundingClientRect(),i=e-a.left,r=t-a.top,s=a.width,o=a.height;this._mouse.x=i/s*2-1,this._mouse.y=-(r/o)*2+1,this._dollyDirection.set(this._mouse.x,this._mouse.y,1).unproject(this.object).sub(this.object.position).normalize()}_clampDistance(e){return Math.max(this.minDistance,Math.min(this.maxDistance,e))}_handleMouseDownRotate(e){this._rotateStart.set(e.clientX,e.clientY)}_handleMouseDownDolly(e){this._updateZoomParameters(e.clientX,e.clientX),this._dollyStart.set(e.clientX,e.clientY)}_handleMouseDownPan(e){this._panStart.set(e.clientX,e.clientY)}_handleMouseMoveRotate(e){this._rotateEnd.set(e.clientX,e.clientY),this._rotateDelta.subVectors(this._rotateEnd,this._rotateStart).multiplyScalar(this.rotateSpeed);const t=this.domElement;this._rotateLeft(It*this._rotateDelta.x/t.clientHeight),this._rotateUp(It*this._rotateDelta.y/t.clientHeight),this._rotateStart.copy(this._rotateEnd),this.update()}_handleMouseMoveDolly(e){this._dollyEnd.set(e.clientX,e.clientY),this._dollyDelta.subVectors(this._dollyEnd,this._dollyStart),this._dollyDelta.y>0?this._dollyOut(this._getZoomScale(this._dollyDelta.y)):this._dollyDelta.y<0&&this._dollyIn(this._getZoomScale(this._dollyDelta.y)),this._dollyStart.copy(this._dollyEnd),this.update()}_handleMouseMovePan(e){this._panEnd.set(e.clientX,e.clientY),this._panDelta.subVectors(this._panEnd,this._panStart).multiplyScalar(this.panSpeed),this._pan(this._panDelta.x,this._panDelta.y),this._panStart.copy(this._panEnd),this.update()}_handleMouseWheel(e){this._updateZoomParameters(e.clientX,e.clientY),e.deltaY<0?this._dollyIn(this._getZoomScale(e.deltaY)):e.deltaY>0&&this._dollyOut(this._getZoomScale(e.deltaY)),this.update()}_handleKeyDown(e){let t=!1;switch(e.code){case this.keys.UP:e.ctrlKey||e.metaKey||e.shiftKey?this._rotateUp(It*this.rotateSpeed/this.domElement.clientHeight):this._pan(0,this.keyPanSpeed),t=!0;break;case this.keys.BOTTOM:e.ctrlKey||e.metaKey||e.shiftKey?this._rotateUp(-It*this.rotateSpeed/this.domElement.clientHeight):this._pan(0,-this.keyPanSpeed),t=!0;break;case this.keys.LEFT:e.ctrlKey||e.metaKey||e.shiftKey?this._rotateLeft(It*this.rotateSpeed/this.domElement.clientHeight):this._pan(this.keyPanSpeed,0),t=!0;break;case this.keys.RIGHT:e.ctrlKey||e.metaKey||e.shiftKey?this._rotateLeft(-It*this.rotateSpeed/this.domElement.clientHeight):this._pan(-this.keyPanSpeed,0),t=!0;break}t&&(e.preventDefault(),this.update())}_handleTouchStartRotate(e){if(this._pointers.length===1)this._rotateStart.set(e.pageX,e.pageY);else{const t=this._getSecondPointerPosition(e),a=.5*(e.pageX+t.x),i=.5*(e.pageY+t.y);this._rotateStart.set(a,i)}}_handleTouchStartPan(e){if(this._pointers.length===1)this._panStart.set(e.pageX,e.pageY);else{const t=this._getSecondPointerPosition(e),a=.5*(e.pageX+t.x),i=.5*(e.pageY+t.y);this._panStart.set(a,i)}}_handleTouchStartDolly(e){const t=this._getSecondPointerPosition(e),a=e.pageX-t.x,i=e.pageY-t.y,r=Math.sqrt(a*a+i*i);this._dollyStart.set(0,r)}_handleTouchStartDollyPan(e){this.enableZoom&&this._handleTouchStartDolly(e),this.enablePan&&this._handleTouchStartPan(e)}_handleTouchStartDollyRotate(e){this.enableZoom&&this._handleTouchStartDolly(e),this.enableRotate&&this._handleTouchStartRotate(e)}_handleTouchMoveRotate(e){if(this._pointers.length==1)this._rotateEnd.set(e.pageX,e.pageY);else{const a=this._getSecondPointerPosition(e),i=.5*(e.pageX+a.x),r=.5*(e.pageY+a.y);this._rotateEnd.set(i,r)}this._rotateDelta.subVectors(this._rotateEnd,this._rotateStart).multiplyScalar(this.rotateSpeed);const t=this.domElement;this._rotateLeft(It*this._rotateDelta.x/t.clientHeight),this._rotateUp(It*this._rotateDelta.y/t.clientHeight),this._rotateStart.copy(this._rotateEnd)}_handleTouchMovePan(e){if(this._pointers.length===1)this._panEnd.set(e.pageX,e.pageY);else{const t=this._getSecondPointerPosition(e),a=.5*(e.pageX+t.x),i=.5*(e.pageY+t.y);this._panEnd.set(a,i)}this._panDelta.subVectors(this._panEnd,this._panStart).multiplyScalar(this.panSpeed),this._pan(this._panDelta.x,this._panDelta.y),this._panStart.copy(this._panEnd)}_handleTouchMoveDolly(e){const t=this._getSecondPointerPosition(e),a=e.pageX-t.x,i=e.pageY-t.y,r=Math.sqrt(a*a+i*i);this._dollyEnd.set(0,r),this._dollyDelta.set(0,Math.pow(this._dollyEnd.y/this._dollyStart.y,this.zoomSpeed)),this._dollyOut(this._dollyDelta.y),this._dollyStart.copy(this._dollyEnd);const s=(e.pageX+t.x)*.5,o=(e.pageY+t.y)*.5;this._updateZoomParameters(s,o)}_handleTouchMoveDollyPan(e){this.enableZoom&&this._handleTouchMoveDolly(e),this.enablePan&&this._handleTouchMovePan(e)}_handleTouchMoveDollyRotate(e){this.enableZoom&&this._handleTouchMoveDolly(e),this.enableRotate&&this._handleTouchMoveRotate(e)}_addPointer(e){this._pointers.push(e.pointerId)}_removePointer(e){delete this._pointerPositions[e.pointerId];for(let t=0;t<this._pointers.length;t++)if(this._pointers[t]==e.pointerId){this._pointers.splice(t,1);return}}_isTrackingPointer(e){for(let t=0;t<this._pointers.length;t++)if(this._pointers[t]==e.pointerId)return!0;return!1}_trackPointer(e){let t=this._pointerPositions[e.pointerId];t===void 0&&(t=new De,this._pointerPositions[e.pointerId]=t),t.set(e.pageX,e.pageY)}_getSecondPointerPosition(e){const t=e.pointerId===this._pointers[0]?this._pointers[1]:this._pointers[0];return this._pointerPositions[t]}_customWheelEvent(e){const t=e.deltaMode,a={clientX:e.clientX,clientY:e.clientY,deltaY:e.deltaY};switch(t){case 1:a.deltaY*=16;break;case 2:a.deltaY*=100;break}return e.ctrlKey&&!this._controlActive&&(a.deltaY*=10),a}}function Ew(n){this.enabled!==!1&&(this._pointers.length===0&&(this.domElement.setPointerCapture(n.pointerId),this.domElement.addEventListener("pointermove",this._onPointerMove),this.domElement.addEventListener("pointerup",this._onPointerUp)),!this._isTrackingPointer(n)&&(this._addPointer(n),n.pointerType==="touch"?this._onTouchStart(n):this._onMouseDown(n)))}function Sw(n){this.enabled!==!1&&(n.pointerType==="touch"?this._onTouchMove(n):this._onMouseMove(n))}function Aw(n){switch(this._removePointer(n),this._pointers.length){case 0:this.domElement.releasePointerCapture(n.pointerId),this.domElement.removeEventListener("pointermove",this._onPointerMove),this.domElement.removeEventListener("pointerup",this._onPointerUp),this.dispatchEvent(Jd),this.state=tt.NONE;break;case 1:const e=this._pointers[0],t=this._pointerPositions[e];this._onTouchStart({pointerId:e,pageX:t.x,pageY:t.y});break}}function Tw(n){let e;switch(n.button){case 0:e=this.mouseButtons.LEFT;break;case 1:e=this.mouseButtons.MIDDLE;break;case 2:e=this.mouseButtons.RIGHT;break;default:e=-1}switch(e){case In.DOLLY:if(this.enableZoom===!1)return;this._handleMouseDownDolly(n),this.state=tt.DOLLY;break;case In.ROTATE:if(n.ctrlKey||n.metaKey||n.shiftKey){if(this.enablePan===!1)return;this._handleMouseDownPan(n),this.state=tt.PAN}else{if(this.enableRotate===!1)return;this._handleMouseDownRotate(n),this.state=tt.ROTATE}break;case In.PAN:if(n.ctrlKey||n.metaKey||n.shiftKey){if(this.enableRotate===!1)return;this._handleMouseDownRotate(n),this.state=tt.ROTATE}else{if(this.enablePan===!1)return;this._handleMouseDownPan(n),this.state=tt.PAN}break;default:this.state=tt.NONE}this.state!==tt.NONE&&this.dispatchEvent(tc)}function kw(n){switch(this.state){case tt.ROTATE:if(this.enableRotate===!1)return;this._handleMouseMoveRotate(n);break;case tt.DOLLY:if(this.enableZoom===!1)return;this._handleMouseMoveDolly(n);break;case tt.PAN:if(this.enablePan===!1)return;this._handleMouseMovePan(n);break}}function Rw(n){this.enabled===!1||this.enableZoom===!1||this.state!==tt.NONE||(n.preventDefault(),this.dispatchEvent(tc),this._handleMouseWheel(this._customWheelEvent(n)),this.dispatchEvent(Jd))}function Cw(n){this.enabled===!1||this.enablePan===!1||this._handleKeyDown(n)}function Iw(n){switch(this._trackPointer(n),this._pointers.length){case 1:switch(this.touches.ONE){case kn.ROTATE:if(this.enableRotate===!1)return;this._handleTouchStartRotate(n),this.state=tt.TOUCH_ROTATE;break;case kn.PAN:if(this.enablePan===!1)return;this._handleTouchStartPan(n),this.state=tt.TOUCH_PAN;break;default:this.state=tt.NONE}break;case 2:switch(this.touches.TWO){case kn.DOLLY_PAN:if(this.enableZoom===!1&&this.enablePan===!1)return;this._handleTouchStartDollyPan(n),this.state=tt.TOUCH_DOLLY_PAN;break;case kn.DOLLY_ROTATE:if(this.enableZoom===!1&&this.enableRotate===!1)return;this._handleTouchStartDollyRotate(n),this.state=tt.TOUCH_DOLLY_ROTATE;break;default:this.state=tt.NONE}break;default:this.state=tt.NONE}this.state!==tt.NONE&&this.dispatchEvent(tc)}function Pw(n){switch(this._trackPointer(n),this.state){case tt.TOUCH_ROTATE:if(this.enableRotate===!1)return;this._handleTouchMoveRotate(n),this.update();break;case tt.TOUCH_PAN:if(this.enablePan===!1)return;this._handleTouchMovePan(n),this.update();break;case tt.TOUCH_DOLLY_PAN:if(this.enableZoom===!1&&this.enablePan===!1)return;this._handleTouchMoveDollyPan(n),this.update();break;case tt.TOUCH_DOLLY_ROTATE:if(this.enableZoom===!1&&this.enableRotate===!1)return;this._handleTouchMoveDollyRotate(n),this.update();break;default:this.state=tt.NONE}}function Dw(n){this.enabled!==!1&&n.preventDefault()}function Nw(n){n.key==="Control"&&(this._controlActive=!0,this.domElement.getRootNode().addEventListener("keyup",this._interceptControlUp,{passive:!0,capture:!0}))}function Uw(n){n.key==="Control"&&(this._controlActive=!1,this.domElement.getRootNode().removeEventListener("keyup",this._interceptControlUp,{passive:!0,capture:!0}))}const Fw=3,Lw=300;function ul(n,e){n.draw(1,e);let t=0,a=0;const i=performance.now();for(;a<Fw&&(a===0||performance.now()-i<Lw);)t+=n.draw(1.5+a,e)?.deformation??0,a++;return t/a}function jw(n){n.scale(n.floor);try{const e=ul(n,!1),t=ul(n,!0);return console.info(`eigendance: deformation ${e.toFixed(1)} ms on the GPU, ${t.toFixed(1)} ms on the CPU per frame`),t<e}finally{n.scale(n.scaleNow)}}const So={target:12,floor:.35,lowerAfterMs:1e3,raiseAfterMs:3e3,raiseAbove:1.6,raiseStep:1.15,settleMs:1200,detail:[1,.5,.25],detailAbove:2.2},Sr=.05,Ss=n=>Math.round(n/Sr)/(1/Sr);class Ow{constructor(e=So){this.rule=e}rule;scale=1;detail=1;lowSince=null;highSince=null;settledAt=-1/0;lowered=!1;get atFloor(){return this.scale<=this.rule.floor+1e-9}get exhausted(){return this.atFloor&&this.detail<=this.rule.detail[this.rule.detail.length-1]}update(e,t,a){const{rule:i}=this;if(!a||!(e>0)||t<this.settledAt)return this.lowSince=this.highSince=null,!1;if(e<i.target&&!this.exhausted){if(this.highSince=null,this.lowSince??=t,t-this.lowSince<i.lowerAfterMs)return!1;if(this.atFloor)return this.setDetail(1,t);const s=this.lowered?.6:0;this.lowered=!0;const o=this.scale*Math.min(.9,Math.max(s,.95*Math.sqrt(e/i.target)));return this.set(Math.max(i.floor,Math.min(this.scale-Sr,Ss(o))),t)}this.lowSince=null;const r=this.detail<1?i.detailAbove:i.raiseAbove;return e>r*i.target&&(this.scale<1||this.detail<1)?(this.highSince??=t,t-this.highSince<i.raiseAfterMs?!1:this.detail<1?this.setDetail(-1,t):this.set(Math.min(1,Math.max(this.scale+Sr,Ss(this.scale*i.raiseStep))),t)):(this.highSince=null,!1)}reset(){this.scale=1,this.detail=1,this.lowSince=this.highSince=null,this.settledAt=-1/0,this.lowered=!1}describe(){if(this.scale>=1&&this.detail>=1)return null;const e=this.detail<1?` and ${Math.round(100*this.detail)}% of the triangles`:"";return`drawing at ${Math.round(100*this.scale)}% resolution${e} to keep ${this.rule.target} fps`}setDetail(e,t){const a=this.rule.detail,i=Math.max(0,Math.min(a.length-1,a.indexOf(this.detail)+e));return this.lowSince=this.highSince=null,this.settledAt=t+this.rule.settleMs,a[i]===this.detail?!1:(this.detail=a[i],!0)}set(e,t){const a=Math.max(this.rule.floor,Math.min(1,Ss(e)));return this.lowSince=this.highSince=null,this.settledAt=t+this.rule.settleMs,Math.abs(a-this.scale)<1e-9?!1:(this.scale=a,!0)}}const ri=30,zw=6,Bw=2e3,Gw=1e3;function Hw(){const n=document.createElement("canvas").getContext("webgl2");if(!n)return!0;const e=n.getExtension("WEBGL_debug_renderer_info"),t=String(e?n.getParameter(e.UNMASKED_RENDERER_WEBGL):"");return n.getExtension("WEBGL_lose_context")?.loseContext(),/swiftshader|llvmpipe|software|softpipe/i.test(t)}class Yd{constructor(e,t,a,i,r,s,o=null,c=null){this.motion=a,this.clock=i,this.stage=r,this.fixedScale=o,this.resolution=new Ow(c===null?So:{...So,target:c}),this.renderer=new Ey({canvas:e,antialias:s,preserveDrawingBuffer:!0,powerPreference:"high-performance"}),o!==null&&(this.resolution.scale=o),this.applyScale(),this.renderer.autoClear=!1,this.controls=new _w(this.playerCamera,t),this.controls.enableDamping=!1,this.controls.addEventListener("change",()=>this.requestDraw())}motion;clock;stage;fixedScale;renderer;studio=new y0;deformer=null;path="gpu";fps=0;frameMs=0;playedFrames=0;onFrame=()=>{};onDrawn=()=>{};resolution;tileCamera=new Pt(ri,1,.05,100);playerCamera=new Pt(ri,1,.05,100);controls;closeUps=new z0(ri);shape=null;rim=null;poses=new WeakMap;framings=new WeakMap;playerFramed=null;pinned=null;drawRequested=!1;cpuBuffers=[];frameTimes=[];requestDraw(){this.drawRequested=!0}time(){return this.pinned??this.clock.now()}pin(e){this.pinned=e}unpin(){this.pinned=null,this.requestDraw()}setBasis(e,t,a=null){const i=new G0(e,this.renderer,t);i.setLook(a),this.deformer?.dispose(),this.deformer=i,i.scene.add(this.studio.backdrop,this.studio.shadow),this.studio.placeShadow(e),this.shape=nn(e.vertices,Xt),this.rim=x0(this.shape,Math.min(1,Bw/e.n)),this.poses=new WeakMap,this.framings=new WeakMap,this.cpuBuffers=[],this.playerFramed=null}start(){const e=()=>{this.clock.ended()&&(this.clock.rewind(),this.requestDraw());const t=this.clock.playing&&this.pinned===null;t||this.drawRequested?(this.drawRequested=!1,this.countFrame(t),this.draw(this.time())):this.countFrame(!1),requestAnimationFrame(e)};requestAnimationFrame(e)}draw(e,t=!1){const a=this.deformer;if(!a||!this.motion.ready)return this.motion.songLoaded&&this.onFrame(e),null;const i=performance.now();this.onFrame(e),this.resize();const r=this.stage(),s=this.renderer;s.setScissorTest(!1),s.setClearColor(1382172,1),s.clear();const o=r.view==="gallery"?r.tiles:r.player?[r.player]:[],c=o.map(b=>this.motion.weights(b.prepared,e));let l=null,h=null;o.length&&(a.useCPU?h=c.map((b,p)=>Va(a.basis,b,this.cpuBuffer(p))):l=a.computePositions(c)),t&&this.finish();const d=performance.now();s.setScissorTest(!0),o.forEach((b,p)=>{const g=r.view==="gallery"?this.tileCamera:this.playerCamera;this.drawShot(b,g,c[p],r,l?.[p]??null,h?.[p]??null)}),s.setScissorTest(!1),t&&this.finish(),this.onDrawn();const f=performance.now();return this.frameMs=this.frameMs?.9*this.frameMs+.1*(f-i):f-i,{deformation:d-i,drawing:f-d}}finish(){const e=this.renderer.getContext();e.readPixels(0,0,1,1,e.RGBA,e.UNSIGNED_BYTE,new Uint8Array(4))}choosePath(e){const t=this.deformer;t.basis.k>B0(this.renderer)?t.useCPU=!0:e?t.useCPU=e==="cpu":t.useCPU=jw({draw:(a,i)=>(t.useCPU=i,this.draw(a,!0)),scale:a=>{this.resolution.scale=a,this.applyScale()},floor:this.resolution.rule.floor,scaleNow:this.resolution.scale}),this.path=t.useCPU?"cpu":"gpu",this.frameMs=0}setPath(e){this.deformer.useCPU=e==="cpu",this.path=e}cpuBuffer(e=0){const t=this.deformer.basis.n*3;for(;this.cpuBuffers.length<=e;)this.cpuBuffers.push(new Float32Array(t));return this.cpuBuffers[e].length!==t&&(this.cpuBuffers[e]=new Float32Array(t)),this.cpuBuffers[e]}bufferRect(e){const t=e.getBoundingClientRect(),a=this.renderer.getPixelRatio();return{x:Math.floor(t.left*a),y:Math.floor(t.top*a),width:Math.floor(t.width*a),height:Math.floor(t.height*a)}}resetPlayerCamera(){this.playerFramed=null,this.requestDraw()}countFrame(e){const t=performance.now();if(!e){this.clock.playing||(this.frameTimes=[],this.fps=0,this.resolution.update(0,t,!1));return}for(this.playedFrames++,this.frameTimes.push(t);this.frameTimes.length>2&&this.frameTimes[0]<t-Gw;)this.frameTimes.shift();const a=t-this.frameTimes[0];this.fps=this.frameTimes.length>1?1e3*(this.frameTimes.length-1)/a:0,this.fixedScale===null&&this.resolution.update(this.fps,t,!0)&&this.applyScale()}get dynamic(){return this.fixedScale===null}applyScale(){const e=Math.min(window.devicePixelRatio,2)*this.resolution.scale;Math.abs(this.renderer.getPixelRatio()-e)>1e-6&&(this.renderer.setPixelRatio(e),this.requestDraw())}drawShot(e,t,a,i,r,s){const o=this.deformer,c=this.renderer,l=e.element.getBoundingClientRect(),h=c.domElement.clientHeight;if(l.width<2||l.height<2||l.bottom<0||l.top>h)return;const d=l.left,f=h-l.bottom;c.setViewport(d,f,l.width,l.height),c.setScissor(d,f,l.width,l.height),this.aim(t,l.width,l.height,e),this.studio.setAspect(l.width/l.height);const{look:b}=e,p=i.view==="player";o.useDetail(p?1:this.resolution.detail),o.setTile(a,s,{color:ec,wireframe:b.shading==="wireframe",deformedNormalWeight:b.shading==="flat"?1:b.deformedNormalWeight,harmonic:p?i.explorer.harmonic:-1,harmonicScale:i.explorer.scale,materials:b.materials},r),c.render(o.scene,t),e.closeUp&&this.closeUps.draw(c,o,this.studio,e.closeUp,h)}aim(e,t,a,i){const r=Math.min(Number(i.element.dataset.covered??0),a/3),s=t/(a-r);if(e.aspect=s,r>0?e.setViewOffset(t,a-r,0,-r,t,a):e.clearViewOffset(),e===this.playerCamera){const l=this.playerFramed;if(!l||l.source!==i.source||Math.abs(s-l.aspect)>.02*s){this.playerFramed={aspect:s,source:i.source};const{target:h,distance:d}=this.framingFor(i.prepared,s);e.position.copy(Xt).multiplyScalar(d).add(h),this.controls.target.copy(h),this.controls.update()}e.updateProjectionMatrix();return}const{target:o,distance:c}=this.framingFor(i.prepared,s);e.position.copy(Xt).multiplyScalar(c).add(o),e.lookAt(o),e.updateProjectionMatrix()}framed(e,t,a,i){const r=t/(a-i),{target:s,distance:o}=this.framingFor(e,r);return{target:s.toArray(),distance:o,direction:Xt.toArray(),fov:ri,aspect:r,covered:i}}framingFor(e,t){const a=Math.round(t*50)/50;let i=this.framings.get(e);i||(i=new Map,this.framings.set(e,i));let r=i.get(a);return r||(r=Gd([this.shape,this.posesOf(e)],Xt,ri,a),i.set(a,r)),r}posesOf(e){let t=this.poses.get(e);if(!t){const a=this.deformer.basis,i=this.rim,r=this.motion.framingWeights?.(e)??this.motion.loudestTimes(zw).map(o=>this.motion.weights(e,o)),s=new Float32Array(3*i.length*r.length);r.forEach((o,c)=>{Va(a,o,s.subarray(3*i.length*c,3*i.length*(c+1)),i)}),t=nn(s,Xt),this.poses.set(e,t)}return t}resize(){const e=window.innerWidth,t=window.innerHeight,a=this.renderer.getSize(new De);(a.x!==e||a.y!==t)&&this.renderer.setSize(e,t,!1)}}class Vw{constructor(e,t,a,i,r,s,o,c=null,l=null){this.events=i,this.path=r,this.batch=s,this.motion=new bw(e);const h={get playing(){return t.playing},now:()=>t.now(),ended:()=>!1,rewind:()=>{}};this.viewer=new Yd(I("rig-gl"),I("rig-player-area"),this.motion,h,()=>this.stage(),a,c,l),this.viewer.onFrame=f=>this.beforeFrame(f);const d=()=>this.viewer.requestDraw();this.gallery=new pw({status:i.status,requestDraw:d,guard:i.guard,songId:()=>i.songId(),combine:f=>this.combine(f),open:(f,b)=>{i.guard("Could not open the dance",()=>this.openDance(f,b))},timeScale:()=>this.player.palette?.time_scale??this.rig?.palette?.time_scale??1,changed:()=>this.keep(),closeUp:f=>O0(this.viewer.deformer.basis,this.motion.framingWeights(f))}),this.player=new vw({requestDraw:d,guard:i.guard,timeScaleChanged:()=>{this.gallery.mode==="modes"&&this.gallery.refresh()},pose:(f,b)=>this.poseJoint(f,b),stiffness:(f,b)=>this.stiffness(f,b),reset:()=>this.reset(),surface:()=>this.surface.genes,changed:()=>{this.surface?.refreshShare(),this.keep()}}),this.motion.surfaceOf=f=>this.surfaceOf(f),this.surface=new ww({rig:()=>this.rig,songId:i.songId,guard:i.guard,play:f=>this.playSurface(f),share:()=>this.surfaceShare(),dances:f=>this.gallery.setSurfaces(f)}),I("rig-player-area").addEventListener("click",f=>this.pickAt(f)),window.addEventListener("resize",()=>{this.active&&this.gallery.layout()});for(const f of["rig-tiles","rig-player-area"])new ResizeObserver(d).observe(I(f));o&&this.viewer.start()}events;path;batch;motion;viewer;gallery;player;surface;rig=null;appearance=null;figure=null;active=!1;view="gallery";tileSurfaces=new WeakMap;sessions=new yw;defaultMapping=null;keeping=!1;async open(e,t){this.events.loading("loading the rig and its vibration modes…"),this.keeping=!1;try{const a=await V0(e);if(!a.k)throw new Error(`${a.name} has no vibration mode (no elastic joint)`);const[i,r]=await Promise.all([rl(e,this.events.songId(),null),this.rigLook(e)]);this.appearance=r,I("rig-materials-switch").hidden=!r,this.gallery.pageSize=t,this.setRig(a,!0),this.defaultMapping=i.default,this.player.show(i.default,"default palette"),this.gallery.setDances(i.mappings),this.gallery.setMode("modes"),this.showSaved(this.sessions.get(e)),this.keeping=!0,this.enter(),this.viewer.choosePath(this.path);const s=`${a.k} vibration mode${a.k===1?"":"s"}`;this.events.status(`${a.name}: ${s}`+(a.edited?" · its pose or stiffness was edited earlier (the server keeps edits; reset pose goes back to the rig as loaded)":""))}finally{this.events.loading(null)}}restore(e){this.sessions.restore(e),this.active&&this.rig&&e[this.rig.id]&&(this.keeping=!1,this.showSaved(e[this.rig.id]),this.keeping=!0)}showSaved(e){if(e&&(this.gallery.restoreDances(e.generations,e.generation,e.selected),!!e.player))try{this.player.show(e.player.mapping,e.player.source)}catch{this.player.show(this.defaultMapping,"default palette")}}keep(){const e=this.rig;if(!this.keeping||!e)return;const t=this.player.saved();this.sessions.set(e.id,{generations:this.gallery.generations,generation:this.gallery.generation,selected:this.gallery.selectedDanceList,player:t?{mapping:t,source:this.player.source}:null})}async songChanged(){if(!this.active||!this.rig)return;const e=await rl(this.rig.id,this.events.songId());this.defaultMapping=e.default,this.gallery.setDances(e.mappings),await this.surface.songChanged()}leave(){this.active=!1,document.body.classList.remove("rig-mode");for(const e of["rig-gallery-view","rig-player-view"])I(e).hidden=!0;I("rig-gl").hidden=!0}setView(e){this.view=e,I("rig-gallery-view").hidden=e!=="gallery",I("rig-player-view").hidden=e!=="player",I("tab-gallery").classList.toggle("active",e==="gallery"),I("tab-player").classList.toggle("active",e==="player"),e==="gallery"&&this.active&&this.gallery.layout(),this.viewer.requestDraw()}stage(){if(!this.active)return{view:this.view,tiles:[],player:null,explorer:{harmonic:-1,scale:1}};const e=this.player.shot(I("rig-player-area"));return{view:this.view,tiles:this.view==="gallery"?this.gallery.shots():[],player:e,explorer:{harmonic:-1,scale:1}}}async openDance(e,t){this.player.show(e,t),this.setView("player"),await this.surface.follow(e.surface??null)}surfaceOf(e){const t=this.motion.surface;if(!t||e===this.player.prepared)return t;const a=this.gallery.surfaceGenes(e);if(!a)return null;let i=this.tileSurfaces.get(e);return(i?.mapping!==a||i.surface!==t.surface)&&(i=new qd(t.surface,a),this.tileSurfaces.set(e,i)),i.gain=t.gain,i}combine(e){const t=this.rig;if(!t||!e.length||!this.defaultMapping)return;const a=1/Math.sqrt(e.length);this.player.show({...this.defaultMapping,modes:{selected:e,amplitudes:e.map(i=>t.tileAmplitudes[i]*a),phases:e.map(i=>t.phases[i]),time_scale:this.player.palette?.time_scale??t.palette.time_scale}},`modes ${e.map(i=>i+1).join(", ")}`),this.setView("player")}poseJoint(e,t){return this.edit("turning the joint",()=>W0(this.rig.id,e,t))}stiffness(e,t){return this.edit("setting the stiffness",()=>q0(this.rig.id,{[this.rig.jointList[e].name]:t}))}reset(){return this.edit("resetting",async()=>{const e=await X0(this.rig.id);return this.player.pick(this.player.joint),e})}enter(){this.active=!0,document.body.classList.add("rig-mode"),I("gallery-view").hidden=!0,I("player-view").hidden=!0,I("rig-gl").hidden=!1,this.setView("gallery")}setRig(e,t){this.motion.surface=null,this.surface.reset(),this.drawRig(e),this.rig=e,this.motion.rig=e,this.player.setRig(e,t),this.gallery.setRig(e,t),t||this.viewer.setPath(this.viewer.path)}drawRig(e){const t=this.motion.surface;this.viewer.setBasis(t?Z0(e,t.surface):Wd(e),this.batch,this.appearance),this.figure?.dispose(),this.figure=new tw(e,this.viewer.deformer.look,t?.surface??null),this.viewer.deformer.scene.add(this.figure.group)}playSurface(e){const t=e===null!=(this.motion.surface===null);this.motion.surface=e,t&&this.rig&&(this.drawRig(this.rig),this.viewer.setPath(this.viewer.path)),this.viewer.requestDraw()}surfaceShare(){const e=this.player.prepared,t=this.viewer.deformer,a=this.motion.music.spectrum;if(!this.motion.surface||!e||!t||!a)return null;const i=[...Array(16).keys()].map(s=>(s+.5)*a.duration/16),r=this.motion.surface;return ew(t.basis,i,(s,o)=>{this.motion.surface=o?r:null;try{return o?this.motion.weights(e,s):br(this.rig,this.motion.coefficients(e,s),new Float32Array(12*t.basis.k4))}finally{this.motion.surface=r}})}async edit(e,t){this.events.status(`${e}…`);const a=performance.now(),i=await t();this.setRig(i,!1),this.events.status(`${i.name}: modes recomputed (${Math.round(performance.now()-a)} ms)`)}beforeFrame(e){const t=this.figure,a=this.viewer.deformer;if(!t||!a)return;const i=this.view==="player"&&this.player.prepared!==null,r=i&&this.player.skinning==="lbs";a.shown=!r,i&&this.poseFigure(e),t.show({lbs:r,bones:i&&this.player.bones,joint:i?this.player.joint:-1,materials:Oa.materials})}poseFigure(e){const t=this.figure,a=this.motion.surface;t.pose(uw(this.rig,this.motion.coefficients(this.player.prepared,e))),t.ripple(a?a.phi(this.motion.music,e):null)}async rigLook(e){const t=(await yl()).rigs?.find(a=>a.id===e);if(!t?.look)return null;try{return await Od("rigs",e)}catch(a){return this.events.status(`${t.name}: its materials cannot be shown (${wa(a)}); drawn in clay`),null}}pickAt(e){if(!this.figure||!this.player.bones)return;const t=I("rig-player-area").getBoundingClientRect(),a=(e.clientX-t.left)/t.width*2-1,i=-((e.clientY-t.top)/t.height)*2+1,r=this.figure.nearestJoint(a,i,this.viewer.playerCamera);r>=0&&this.player.pick(r)}}class Ww{constructor(e=()=>new AudioContext){this.createContext=e}createContext;duration=0;loop=!1;onChange=()=>{};onEnd=()=>{};context=null;mix=null;output=null;buffer=null;source=null;startedAt=0;offset=0;isPlaying=!1;loudness=1;silenced=!1;live=null;get playing(){return this.live?this.live.playing:this.isPlaying}get following(){return this.live!==null}follow(e){this.pause(),this.live=e,this.applyVolume(),this.onChange(this.playing)}get audioContext(){return this.audio()}get input(){return this.audio(),this.mix}get volume(){return this.loudness}set volume(e){this.loudness=Math.max(0,Math.min(1,e)),this.applyVolume()}get muted(){return this.silenced}set muted(e){this.silenced=e,this.applyVolume()}now(){if(this.live)return this.live.now();const e=this.isPlaying&&this.context?this.context.currentTime-this.startedAt:this.offset;return Math.min(e,this.duration)}ended(){return this.live?!1:this.isPlaying&&this.context!==null&&this.context.currentTime-this.startedAt>=this.duration}async load(e,t){this.pause(),this.buffer=null,this.duration=t,this.offset=0,e!==null&&(this.buffer=await this.audio().decodeAudioData(e))}play(){if(this.live){this.audio().resume();return}if(this.isPlaying||!this.buffer)return;const e=this.audio();e.resume();const t=e.createBufferSource();t.buffer=this.buffer,t.connect(this.mix),t.start(0,this.offset),this.source=t,this.startedAt=e.currentTime-this.offset,this.isPlaying=!0,this.onChange(!0)}pause(){if(this.isPlaying){this.offset=this.now(),this.isPlaying=!1;try{this.source?.stop()}catch{}this.source=null,this.onChange(!1)}}seek(e){if(this.live)return;const t=this.isPlaying;this.pause(),this.offset=Math.max(0,Math.min(e,this.duration)),t&&this.play()}rewind(){this.live||(this.pause(),this.offset=0,this.loop?this.play():this.onEnd())}tap(){const e=this.audio().createMediaStreamDestination();return this.mix.connect(e),e}untap(e){this.mix?.disconnect(e)}audio(){return this.context||(this.context=this.createContext(),this.mix=this.context.createGain(),this.output=this.context.createGain(),this.mix.connect(this.output),this.output.connect(this.context.destination),this.applyVolume()),this.context}applyVolume(){this.output&&(this.output.gain.value=this.silenced||this.live?0:this.loudness)}}const qw=500,bl="ready: press ▶ or space";class Zd{constructor(e){this.options=e;const t=e.aa??(e.render||!Hw()),a=this.messages;this.viewer=new Yd(I("gl"),I("player-area"),this.motion,this.transport,()=>this.stage(),t,e.scale,e.fps),this.viewer.onFrame=o=>{this.rigs?.active&&this.rigs.viewer.requestDraw(),this.showFrame(o),fx(I("spectrum"),this.motion.bandValuesAt(o)),hx(I("spectrum"),this.motion.spectrum,o)};const i=()=>this.viewer.requestDraw(),r=o=>a.status(o),s=(o,c)=>a.guard(o,c);this.gallery=new vx(this.motion,{status:r,requestDraw:i,guard:s,songId:()=>this.library.songId,modelName:()=>this.library.meshName,open:o=>this.open(o,`tile of generation ${this.gallery.generation+1}`)},null),this.player=new d0(this.motion,{requestDraw:i,upload:o=>{this.files.handle([o])},modelName:()=>this.library.meshName,harmonicScale:o=>this.viewer.deformer?.harmonicScale(o)??1}),this.recorder=new g0(this.transport,[I("record"),I("rig-record")],()=>this.play(),()=>({viewer:this.shownViewer(),name:this.modelName(),element:I(this.rigs.active?"rig-player-area":"player-area")})),this.library=new i0(e,this.motion,this.viewer,this.transport,(o,c)=>a.loading(o,c),o=>a.error(o)),this.library.onBasis=()=>{this.gallery.refresh(),this.player.basisChanged()},this.live=new Kx({transport:this.transport,motion:this.motion,error:o=>a.error(o),status:r,requestDraw:()=>this.requestDraws(),restoreSong:()=>this.restoreSong(),songAdded:async o=>{await this.library.refresh(),this.live.fillMenu(I("song"))},fps:()=>this.shownViewer().fps}),this.library.onMenus=()=>this.live.fillMenu(I("song")),this.rigs=new Vw(this.motion,this.transport,t,{status:r,loading:o=>a.loading(o),guard:s,songId:()=>this.library.songId},e.path,e.batch,!e.render,e.scale,e.fps),this.files=new Uf(a,{refresh:async()=>{await this.library.refresh()},started:()=>this.started,startIfComplete:async()=>this.loadFirst(await this.library.refresh()),openRig:o=>this.openRig(o),showMesh:o=>this.showMesh(o),changeSong:o=>this.changeSong(o),openMapping:(o,c,l)=>this.open(c,l),requestDraw:i}),this.frameRate=new Zf({viewer:()=>this.shownViewer(),galleryTiles:()=>this.view==="gallery"&&!this.rigs.active?this.gallery.tileCount:null,playing:()=>this.transport.playing,smallest:()=>this.rule?.min??2,newGallery:o=>this.newGallery(o)}),this.exporter=new yf(a,{dance:()=>this.exportedDance(),now:()=>this.viewer.time(),duration:()=>this.motion.duration,live:()=>this.transport.following}),this.transport.onChange=o=>{I("play").textContent=o?"❚❚":"▶",this.frameRate.restart(),a.playing(o)},Jx(this),a.wire(),this.files.wire()}options;messages=new s0;motion=new l0;transport=new Ww;viewer;gallery;player;library;recorder;files;frameRate;exporter;rigs;live;view="gallery";rule=null;started=!1;notice="";readoutAt=0;async start(){document.body.classList.toggle("bare",this.options.bare),this.options.render||this.viewer.start(),this.options.render||this.options.test||this.options.bare||this.messages.helpOnFirstVisit();try{await this.readConfig(),await this.loadFirst($y(this,await this.library.refresh()))}catch(t){this.messages.error(`The page could not start: ${wa(t)}`)}}setView(e){if(this.view=e,(e!=="gallery"||this.rigs.active)&&this.frameRate.hideNotice(),this.exporter.refresh(),this.rigs.active){this.rigs.setView(e);return}I("gallery-view").hidden=e!=="gallery",I("player-view").hidden=e!=="player",I("tab-gallery").classList.toggle("active",e==="gallery"),I("tab-player").classList.toggle("active",e==="player");const t=this.gallery.mappings()[0];e==="player"&&!this.player.mapping&&t&&this.open(t,"tile 1"),e==="gallery"&&this.gallery.refresh(),this.player.refreshInfo(this.viewer.path),this.viewer.requestDraw()}openRig(e){return this.frameRate.hideNotice(),this.messages.guard("Could not show this rig",async()=>{if(!this.started){const t=await this.library.refresh();t.songs.length&&await ms(this,t),this.started=t.songs.length>0}await this.rigs.open(e,this.rule?.max??16),I("mesh").value=`rig:${e}`,this.view="gallery",this.exporter.refresh()})}open(e,t=""){this.player.show(e,t),this.view!=="player"&&this.setView("player"),this.exporter.refresh(),this.viewer.requestDraw()}play(){this.transport.play(),this.transport.playing&&this.viewer.unpin()}togglePlay(){this.transport.playing?this.transport.pause():this.play()}async newGallery(e){const{meshId:t,songId:a}=this.library,i=`${this.library.meshName}, ${this.library.songName}`,r=await this.messages.guard("Could not make the gallery",()=>this.gallery.create(t,a,i,e===void 0?this.gallery.size:e));return this.gallery.size!==null&&this.fillSizeMenu(this.gallery.size),r}async showMesh(e){if(!await this.library.loadMesh(e))return"removed while it was computed";this.rigs.active&&(this.rigs.leave(),this.setView(this.view));const t=this.gallery.showMesh(e)?null:await this.newGallery();return this.gallery.size!==null&&this.fillSizeMenu(this.gallery.tileCount||this.gallery.size),this.viewer.choosePath(this.options.path),this.exporter.refresh(),t}async changeSong(e){this.live.stop(),await this.library.loadSong(e),Gn({song:pi(this)}),await this.newGallery(),await this.rigs.songChanged(),this.exporter.refresh(),this.viewer.requestDraw()}startLive(e){return this.live.start(e)}async startAskedSource(){const{source:e,badSource:t}=this.options;t!==null?this.messages.error(`?source=${t} is not a live input (?source=mic: a microphone or line in; ?source=tab: a tab's audio); the song plays instead`):e&&!await this.startLive({kind:e})&&this.messages.status("the song plays instead of the live input (see above)")}async restoreSong(){this.library.songId&&await this.library.loadSong(this.library.songId),this.requestDraws()}requestDraws(){this.viewer.requestDraw(),this.rigs.active&&this.rigs.viewer.requestDraw()}modelName(){return this.rigs.active?this.rigs.rig?.name??"":this.library.meshName}shownViewer(){return this.rigs.active?this.rigs.viewer:this.viewer}exportedDance(){const e=this.library.songId;if(this.rigs.active){if(this.rigs.view!=="player")return null;const a=this.rigs.player.saved();return a&&this.rigs.rig?{kind:"rig",id:this.rigs.rig.id,song:e,mapping:a,name:this.rigs.rig.name}:null}if(this.view!=="player")return null;const t=this.player.saved();return t?{kind:"mesh",id:this.library.meshId,song:e,mapping:t,name:this.library.meshName}:null}stage(){return this.rigs.active?{view:this.view,tiles:[],player:null,explorer:this.player.explorer}:{view:this.view,tiles:this.gallery.shots(),player:this.player.shot(I("player-area")),explorer:this.player.explorer}}showFrame(e){const t=I("seek");document.activeElement!==t&&(t.value=String(e));const a=Math.floor(e);I("clock").textContent=`${Math.floor(a/60)}:${String(a%60).padStart(2,"0")}`;const i=performance.now();i-this.readoutAt<qw||(this.readoutAt=i,this.view==="player"&&this.player.refreshInfo(this.viewer.path),this.frameRate.update(i),this.live.refresh())}async readConfig(){try{const a=await hf();this.files.suffixes=Lf(a),this.rule=qf(a)}catch(a){this.rule=null,this.messages.error(`Could not read the gallery sizes from the server (${wa(a)}); the server will check the size asked for`)}const{size:e,problem:t}=Xf(this.options.size,this.rule);this.notice=t??"",this.notice&&this.messages.status(this.notice),this.gallery.size=e,this.fillSizeMenu(e)}async loadFirstRig(e,t){await ms(this,e),this.started=!0;const a=await this.openRig(t);return this.options.view==="player"&&this.setView("player"),a||this.messages.hint(this.options.render?"render mode":bl,this.transport.playing),await this.live.listDevices(),await this.startAskedSource(),!0}fillSizeMenu(e){const t=I("size");if(t.innerHTML="",e!==null){for(const a of Kf(this.rule,e))t.add(new Option(String(a)));t.value=String(e)}}async loadFirst(e){const t=ex(e,this.options.mesh);if(t.rig&&e.songs.length)return this.loadFirstRig(e,t.rig);if(!e.meshes.length||!e.songs.length){const o=e.meshes.length?"a song":"a model";return this.messages.status(`the library needs ${o}: drop a file here`),!1}const{options:a}=this;await ms(this,e),await this.library.loadMesh(a.mesh??t.mesh??e.meshes[0].id),this.started=!0;let i=this.gallery.showMesh(this.library.meshId)?null:await this.newGallery();i&&this.gallery.size!==null&&this.rule===null&&(i=await this.newGallery(null));const r=a.mapping??e.mappings.find(o=>o.origin==="file")?.id??null;if(r){const o=e.mappings.find(c=>c.id===r)?.name??"mapping";I("mapping-menu").value=r,this.player.show(await ia(`api/mappings/${r}`),o)}this.setView(a.view??(r?"player":"gallery")),this.viewer.choosePath(a.path),this.viewer.draw(this.viewer.time()),this.player.refreshInfo(this.viewer.path);const s=a.render?"render mode":bl;return i?this.messages.status(""):this.messages.hint(this.notice?`${this.notice} · ${s}`:s,this.transport.playing),this.notice="",await this.live.listDevices(),await this.startAskedSource(),!0}}function Xw(n){const e=n.live;return{start:(t="mic",a)=>n.startLive({kind:t,deviceId:a}),stop:()=>e.leave(),save:()=>e.saveTake(),setOffset:t=>e.setOffset(t),unplug:()=>e.input?.mediaStream.getAudioTracks().forEach(t=>t.dispatchEvent(new Event("ended"))),state:()=>{const t=e.input,a=t?.take.spectrum;return{active:e.active,name:t?.name??null,frames:a?.frames??0,seconds:a?.duration??0,tempo:a?.tempo??0,estimate:t?.take.rhythm.tempo??0,onsets:t?[...t.take.rhythm.onsets]:[],beats:t?[...t.take.rhythm.beats]:[],sampleRate:n.transport.audioContext.sampleRate,window:t?new Vh(n.transport.audioContext.sampleRate).N:0,latency:t?.latency??0,offset:t?.offset??0,stats:t?.stats??null,info:document.getElementById("live-info").textContent,menu:document.getElementById("song").value,following:n.transport.following,running:e.history.filter(i=>i.running).length,liveTracks:e.history.flatMap(i=>i.mediaStream.getTracks()).filter(i=>i.readyState!=="ended").length,opened:e.history.length,receiveMs:t?.receiveMs??0}},values:(t=0,a)=>{const i=e.input?.take.spectrum;if(!i)return[];const r=Math.min(a??i.frames,i.frames),s=[];for(let o=t;o<r;o++)s.push(Array.from(i.values.subarray(o*i.bands,(o+1)*i.bands)));return s},onsetStrength:()=>{const t=e.input?.take.spectrum;return t?Array.from(t.onsetStrength.subarray(0,t.frames)):[]},timeAnalysis:(t=10,a=48e3)=>{const i=new Vh(a),r=new Float32Array(128),s=Math.round(t*a/128);let o=1;const c=performance.now();for(let l=0;l<s;l++){for(let h=0;h<128;h++)o=o*16807%2147483647,r[h]=o/2147483647-.5;i.push(r)}return(performance.now()-c)/s}}}function Kw(n){return{...Jw(n),...Yw(n),...Zw(n)}}function Jw(n){const e=n.rigs,t=i=>i==="player"?e.player.prepared:e.gallery.shots()[i].prepared,a=i=>e.gallery.shots().map(r=>e.motion.weights(r.prepared,i));return{open:i=>n.openRig(i),renderAt(i){e.viewer.pin(i),e.viewer.draw(i),e.viewer.finish()},live:()=>e.viewer.unpin(),readPositions(i,r){const s=e.viewer.deformer,o=i==="player"?s.readPositions([e.motion.weights(t(i),r)]):s.readPositions(a(r),i);return Array.from(_s(e.rig,o))},readTiles(i){return e.viewer.deformer.readAll(a(i)).map(r=>Array.from(_s(e.rig,r)))},cpuPositions(i,r){const s=e.viewer.deformer.basis;return Array.from(_s(e.rig,Va(s,e.motion.weights(t(i),r))))},coefficients:(i,r)=>Array.from(e.motion.coefficients(t(i),r)),lbsPositions(i){return e.poseFigure(i),Array.from(e.figure.lbsPositions())},tilePixels:(i=4)=>gi(e.viewer,e.gallery.views(),i),tileBytes:(i=4)=>gi(e.viewer,e.gallery.views(),i).map(r=>Qw(r)),playerPixels:(i=4)=>gi(e.viewer,[document.getElementById("rig-player-area")],i)[0],labels:()=>e.gallery.labels(),closeUps:()=>e.gallery.closeUpsShown()}}function Yw(n){const e=n.rigs;return{setView:t=>n.setView(t),setMode:t=>e.gallery.setMode(t),page:t=>e.gallery.setPage(t),pageSize:t=>{e.gallery.pageSize=t,e.gallery.setMode("modes"),e.gallery.setPage(0)},select:t=>e.gallery.toggle(t),combine:()=>e.combine(e.gallery.selection),breed:t=>n.messages.guard("Breeding failed",()=>e.gallery.breed(t)),openDance:t=>{const a=e.openDance(e.gallery.dance(t),`dance ${t+1}`);return n.setView("player"),a},dance:t=>e.gallery.dance(t),setSkinning:t=>{e.player.skinning=t,document.getElementById("rig-skinning").value=t,e.viewer.requestDraw()},setMusic:t=>{e.player.music=t,document.getElementById("rig-music").checked=t,e.player.update()},setMaterials:t=>{Oa.materials=t,document.getElementById("rig-materials").checked=t,e.viewer.requestDraw()},look:()=>Ao(e.viewer),setBones:t=>{e.player.bones=t,document.getElementById("rig-bones").checked=t,e.viewer.requestDraw()},pick:t=>e.player.pick(t)}}function Zw(n){const e=n.rigs;return{scaleAmplitudes:t=>{const a=e.player.palette.amplitudes;a.forEach((i,r)=>{a[r]=i*t}),e.player.update()},pose:(t,a)=>n.messages.guard("Could not turn the joint",()=>e.poseJoint(t,a)),stiffness:(t,a)=>n.messages.guard("Could not set the stiffness",()=>e.stiffness(t,a)),reset:()=>n.messages.guard("Could not reset the rig",()=>e.reset()),playerMapping:()=>e.player.saved(),info:()=>({id:e.rig?.id,name:e.rig?.name,n:e.rig?.n,k:e.rig?.k,revision:e.rig?.revision,diagonal:e.rig?.diagonal,active:e.active,view:e.view,mode:e.gallery.mode,page:e.gallery.page,pages:e.gallery.pages,modes:e.gallery.modes,tiles:e.gallery.views().length,path:e.viewer.path,batch:e.viewer.deformer?.batch,fps:e.viewer.fps,frequencies:e.rig?Array.from(e.rig.frequencies):[],generations:e.gallery.generations.length,error:n.messages.shownError(),info:document.getElementById("rig-info").textContent}),setPath:t=>e.viewer.setPath(t),timeFrames(t,a=1){e.viewer.draw(a),e.viewer.finish();const i=performance.now();for(let r=0;r<t;r++)e.viewer.draw(a+.1*r),e.viewer.finish();return{frame:(performance.now()-i)/t}}}}function Qw(n){let e="";for(let t=0;t<n.length;t+=8192)e+=String.fromCharCode(...n.slice(t,t+8192));return btoa(e)}function Ao(n){const e=n.deformer?.look;return e?{materials:e.appearance.materials.map(t=>t.name),drawn:e.appearance.drawn,images:e.appearance.images.length}:null}function gi(n,e,t){const a=n.renderer.getContext(),i=n.renderer.domElement.height,r=n.renderer.getPixelRatio();return e.map(s=>{const o=s.getBoundingClientRect(),c=Math.floor(o.width*r),l=Math.floor(o.height*r),h=new Uint8Array(c*l*4);a.readPixels(Math.floor(o.left*r),i-Math.floor(o.bottom*r),c,l,a.RGBA,a.UNSIGNED_BYTE,h);const d=[];for(let f=0;f<l;f+=t)for(let b=0;b<c;b+=t){const p=4*(f*c+b);d.push(h[p],h[p+1],h[p+2])}return d})}function ml(n,e){window.eigendance=$w(n,e),console.info("eigendance: test hooks on window.eigendance")}function $w(n,e){return{ready:e,...eM(n),...tM(n),rig:Kw(n),liveInput:Xw(n),...aM(n)}}const Qd=(n,e)=>n.gallery.shots().map(t=>n.motion.weights(t.prepared,e));function eM(n){const{gallery:e,motion:t,player:a,viewer:i}=n,r=s=>s==="player"?a.prepared:e.shots()[s].prepared;return{async renderAt(s){i.pin(s),i.draw(s),i.finish()},live(){i.unpin()},readPositions(s,o,c=!1){const l=i.deformer;return Array.from(s==="player"||c?l.readPositions([t.weights(r(s),o)]):l.readPositions(Qd(n,o),s))},cpuPositions(s,o){return Array.from(Va(t.basis,t.weights(r(s),o)))},framingOf(s){const o=s==="player"?document.getElementById("player-area"):e.views()[s],{width:c,height:l}=o.getBoundingClientRect();return i.framed(r(s),c,l,Math.min(Number(o.dataset.covered??0),l/3))},tilePixels:(s=4)=>gi(i,e.views(),s),playerPixels:(s=4)=>gi(i,[document.getElementById("player-area")],s)[0]}}function tM(n){const{gallery:e,motion:t,player:a,viewer:i}=n;return{mappings:()=>e.mappings(),playerMapping:()=>a.saved(),select:r=>e.toggle(r),breed:async r=>{await n.messages.guard("Breeding failed",()=>e.breed(r))},back:()=>e.step(-1),generation:r=>e.setGeneration(r),generations:()=>e.history.entries(),setView:r=>n.setView(r),open:r=>n.open(e.mappings()[r],`tile ${r+1}`),upload:r=>n.files.handle([r]),info:()=>({meshId:n.library.meshId,songId:n.library.songId,n:t.basis?.n,k:t.basis?.k,path:i.path,batch:i.deformer?.batch,generation:e.generation,generations:e.generationCount,tiles:e.tileCount,view:n.view,frameMs:i.frameMs,fps:i.fps,frames:i.playedFrames,duration:t.duration,selected:e.selection,playing:n.transport.playing,time:n.transport.now(),volume:n.transport.volume,muted:n.transport.muted,error:n.messages.shownError(),scale:i.resolution.scale,status:document.getElementById("status").textContent,recording:n.recorder.size,look:Ao(i)}),setPath:r=>i.setPath(r),setMaterials(r){for(const s of[...e.mappings(),a.mapping])s&&(s.look={...s.look,materials:r});document.getElementById("materials").checked=r,i.requestDraw()},look:()=>Ao(i),resolution:()=>({scale:i.resolution.scale,atFloor:i.resolution.atFloor,detail:i.resolution.detail,exhausted:i.resolution.exhausted,said:i.resolution.describe(),pixelRatio:i.renderer.getPixelRatio()}),setDetail(r){i.resolution.detail=r,i.requestDraw()},exportRequest:()=>n.exporter.request()}}function aM(n){const{motion:e,viewer:t}=n;return{timeDeformation(a,i=1){const r=o=>{const c=Qd(n,o),l=t.deformer;l.useCPU?c.forEach((h,d)=>Va(e.basis,h,t.cpuBuffer(d))):l.computePositions(c),t.finish()};r(i);const s=performance.now();for(let o=0;o<a;o++)r(i+.1*o);return{frame:(performance.now()-s)/a}},timeFrames(a,i=1){t.draw(i),t.finish();const r=performance.now();for(let s=0;s<a;s++)t.draw(i+.1*s),t.finish();return{frame:(performance.now()-r)/a}},profileFrames(a,i=1){t.draw(i,!0);let r=0,s=0;for(let o=0;o<a;o++){const c=t.draw(i+.1*o,!0);r+=c.deformation,s+=c.drawing}return{deformation:r/a,drawing:s/a}}}}const Tn=n=>`api/presets/${encodeURIComponent(n)}`;async function si(n,e,t){return(await Bt(await fetch(e,{method:n,headers:t===void 0?{}:{"Content-Type":"application/json"},body:t===void 0?void 0:JSON.stringify(t)}))).json()}class nM{constructor(e){this.app=e,this.element=document.createElement("aside"),this.element.id="presets-panel",this.element.hidden=!0,this.element.innerHTML=`
      <div class="row"><strong>presets</strong><button id="presets-close" aria-label="close">×</button></div>
      <div class="row"><input id="preset-name" placeholder="name" maxlength="64" size="14">
        <input id="preset-tags" placeholder="tags, comma separated" size="14">
        <button id="preset-save" title="save the player's dance (mapping or palette, look, a picture of it) as a preset">save</button></div>
      <div class="row"><input id="preset-search" type="search" placeholder="search name or tag" size="16">
        <label><input id="preset-favourites" type="checkbox"> ★ only</label>
        <label class="upload" title="import preset files">import <input id="preset-import" type="file" accept=".json" multiple hidden></label></div>
      <div id="preset-list"></div>
      <div id="preset-status" class="tags"></div>`,document.body.append(this.element);const t=document.createElement("button");t.id="presets-button",t.textContent="presets",t.title="presets: save, browse and play named dances",document.querySelector("#bar nav")?.append(t),t.addEventListener("click",()=>this.toggle()),this.wire()}app;element;presets=[];toggle(e=this.element.hidden){this.element.hidden=!e,e&&this.refresh()}async refresh(){const e=(this.input("preset-search").value||"").trim(),t=this.input("preset-favourites").checked?"&favourites=1":"";this.presets=await ia(`api/presets?q=${encodeURIComponent(e)}${t}`),this.element.querySelector("#preset-list").replaceChildren(...this.presets.map(i=>this.row(i)))}async save(e,t,a=!1){const i=this.app,r=i.rigs.active,s=r?i.rigs.player.saved():i.player.saved();if(!s)return this.say("open a dance in the player first");const o=document.getElementById(r?"rig-gl":"gl"),c=iM(o);try{await si("POST","api/presets",{name:e,mapping:s,tags:t,thumbnail:c,replace:a,mesh:r?void 0:i.library.meshId||void 0})}catch(l){return this.say(String(l.message??l))}return this.say(`saved ${e}`),await this.refresh(),null}async play(e){const t=this.app,a=t.rigs.active&&t.rigs.rig?`rig=${t.rigs.rig.id}`:`mesh=${t.library.meshId}`,i=await ia(`${Tn(e)}?${a}`);t.rigs.active?await t.rigs.openDance(i.mapping,e):t.open(i.mapping,`preset ${e}`)}row(e){const t=document.createElement("div");t.className="preset",t.dataset.name=e.name;const a=e.thumbnail?`<img alt="" src="${Tn(e.name)}/thumbnail.png">`:'<img alt="">';t.innerHTML=`${a}<span class="name"></span>
      <button class="fav" title="favourite (on the keys 1–9)">${e.favourite?"★":"☆"}</button>
      <button class="play" title="play it in the player">▶</button>
      <button class="rename" title="rename">✎</button>
      <a class="export" title="download the preset file" download>⇩</a>
      <button class="delete remove" title="delete" aria-label="delete">✕</button>`,t.querySelector(".name").textContent=e.name;const i=document.createElement("div");i.className="tags",i.textContent=e.tags.join(", "),t.querySelector(".name").append(i),t.querySelector(".export").href=`${Tn(e.name)}/file`;const r=(s,o)=>t.querySelector(`.${s}`).addEventListener("click",()=>{this.guard(o)});return r("fav",()=>si("PATCH",Tn(e.name),{favourite:!e.favourite})),r("play",()=>this.play(e.name)),r("rename",async()=>{const s=prompt("new name",e.name);s&&s!==e.name&&await si("PATCH",Tn(e.name),{name:s})}),r("delete",async()=>{confirm(`delete the preset ${e.name}?`)&&await si("DELETE",Tn(e.name))}),t}async guard(e){try{await e()}catch(t){this.say(String(t.message??t))}await this.refresh()}say(e){return this.element.querySelector("#preset-status").textContent=e,e}input(e){return this.element.querySelector(`#${e}`)}wire(){this.element.querySelector("#presets-close").addEventListener("click",()=>this.toggle(!1)),this.element.querySelector("#preset-save").addEventListener("click",()=>{const e=this.input("preset-tags").value.split(",").map(t=>t.trim()).filter(Boolean);this.save(this.input("preset-name").value.trim(),e)}),this.input("preset-search").addEventListener("input",()=>{this.refresh()}),this.input("preset-favourites").addEventListener("change",()=>{this.refresh()}),this.input("preset-import").addEventListener("change",async e=>{const t=e.target;for(const a of Array.from(t.files??[]))await this.guard(async()=>si("POST","api/presets",JSON.parse(await a.text())));t.value=""})}}function iM(n,e=192){if(!n||!n.width)return null;const t=document.createElement("canvas");return t.width=e,t.height=Math.max(1,Math.round(e*n.height/n.width)),t.getContext("2d")?.drawImage(n,0,0,t.width,t.height),t.toDataURL("image/png")}const $d=[[["PageDown","."],"next cue","next"],[["PageUp",","],"previous cue","prev"],[["1","2","3","4","5","6","7","8","9"],"preset slots 1–9","slot"],[["t"],"tap tempo (the show's beats)","tap"],[["a"],"auto: the song's own beats again","auto"],[["k"],"blackout","blackout"],[["c"],"loop this cue","loop_cue"],[["o"],"the output page (/show)","output"]];async function qt(n,e){try{return await cn("api/show/control",{action:n,value:e})}catch(t){return console.warn(`eigendance show: ${n}: ${String(t)}`),null}}class rM{element;state=null;onPreset=()=>{};constructor(){this.element=document.createElement("aside"),this.element.id="show-panel",this.element.hidden=!0,this.element.innerHTML=`
      <div class="row"><strong id="show-set">show</strong>
        <a id="show-output" href="show" target="eigendance-show" title="the output page for the projector (O)">output ↗</a></div>
      <ol id="show-cues"></ol>
      <div class="row">
        <button id="show-prev" title="previous cue (PageUp or ,)">◀ cue</button>
        <button id="show-next" title="next cue, on the next downbeat (PageDown or .)">cue ▶</button>
        <button id="show-loop-cue" title="stay on this cue when it ends (C)">loop cue</button>
        <button id="show-loop-set" title="after the last cue, the first again">loop set</button>
      </div>
      <div class="row">
        <button id="show-play" title="play / stop the show">▶ play</button>
        <button id="show-blackout" title="black output (K)">blackout</button>
        <button id="show-tap" title="tap the tempo: the show's beats, from the first tap's downbeat (T)">tap</button>
        <button id="show-auto" title="the song's own beats again, after tapping (A)">auto</button><span id="show-tempo"></span>
      </div>
      <div class="row"><label title="the show's gain: how far every dance moves">gain
        <input id="show-gain" type="range" min="0" max="4" step="0.01" value="1"></label>
        <label title="crossfade of a change, beats">fade
        <input id="show-fade" type="number" min="0" max="64" step="1" value="4" style="width:4em"></label></div>`,document.body.append(this.element),this.wire()}async start(){try{this.render(await ia("api/show/state"))}catch{return}const e=new EventSource("api/show/events");e.onmessage=t=>this.render(JSON.parse(t.data)),window.addEventListener("keydown",t=>this.key(t))}render(e){const t=this.state;this.state=e,t&&t.preset!==e.preset&&this.onPreset(e.preset),this.element.hidden=e.set===null;const a=o=>document.getElementById(o);a("show-set").textContent=e.set??"show",a("show-cues").replaceChildren(...e.cues.map((o,c)=>{const l=document.createElement("li"),h=o.until==="bars"?`${o.bars} bars`:o.until==="section"?"to the next section":"until told";return l.textContent=`${o.name} · ${o.preset??"first tile"} · ${h}${o.loop?" · loop":""}`,l.classList.toggle("current",c===e.cue),l.classList.toggle("next",c===e.next),l.addEventListener("click",()=>{qt("cue",c)}),l})),a("show-loop-cue").classList.toggle("active",e.loop_cue===!0),a("show-loop-set").classList.toggle("active",e.loop_set),a("show-blackout").classList.toggle("active",e.blackout),a("show-play").textContent=e.playing?"■ stop":"▶ play",a("show-tempo").textContent=e.tempo?`${e.tempo.toFixed(1)} BPM${e.grid?` · ${e.grid.source}`:""}`:"",a("show-auto").classList.toggle("active",e.grid===null);const r=a("show-gain");document.activeElement!==r&&(r.value=String(e.gain));const s=a("show-fade");document.activeElement!==s&&(s.value=String(e.fade_beats))}wire(){const e=(i,r)=>this.element.querySelector(`#${i}`).addEventListener("click",r);e("show-prev",()=>{qt("prev")}),e("show-next",()=>{qt("next")}),e("show-loop-cue",()=>{qt("loop_cue")}),e("show-loop-set",()=>{qt("loop_set")}),e("show-blackout",()=>{qt("blackout")}),e("show-tap",()=>{qt("tap")}),e("show-auto",()=>{qt("auto")}),e("show-play",()=>{qt(this.state?.playing?"stop":"play")});const t=this.element.querySelector("#show-gain");t.addEventListener("input",()=>{qt("gain",Number(t.value))});const a=this.element.querySelector("#show-fade");a.addEventListener("change",()=>{qt("fade",Number(a.value))})}key(e){if(!Td(e))return;const t=Ad(e),a=$d.find(([i])=>i.includes(t))?.[2];a&&(e.preventDefault(),a==="output"?window.open("show","eigendance-show"):qt(a,a==="slot"?Number(t):void 0))}}function sM(){kd($d.map(([n,e])=>[n,e]))}const pl="eigendance.midi",oM=600;function cM(n){if(!n||n.length<1)throw new Error("an empty MIDI message");const e=n[0];if(e<128)throw new Error(`a MIDI message without a status byte (${e})`);const t=e&240,a=e&15;if(t!==176&&t!==144&&t!==128)return null;if(n.length<3||n[1]>127||n[2]>127)throw new Error(`a malformed MIDI message (${Array.from(n).join(" ")})`);return t===176?{key:`cc:${a}:${n[1]}`,value:n[2]/127}:{key:`note:${a}:${n[1]}`,value:t===144&&n[2]>0?1:0}}class hM{map={};learning=null;pressed=new Set;constructor(){try{this.map=JSON.parse(localStorage.getItem(pl)??"{}")}catch{this.map={}}document.addEventListener("contextmenu",t=>{const a=gl(t.target);a&&(t.preventDefault(),this.learn(a))});let e=0;document.addEventListener("pointerdown",t=>{const a=gl(t.target);a&&t.pointerType==="touch"&&(e=window.setTimeout(()=>this.learn(a),oM))}),document.addEventListener("pointerup",()=>window.clearTimeout(e)),this.mark()}async start(){const e=navigator.requestMIDIAccess;if(!e)return!1;try{const t=await e.call(navigator),a=()=>t.inputs.forEach(i=>{i.onmidimessage=r=>this.message(r.data)});return a(),t.onstatechange=a,!0}catch(t){return console.warn(`eigendance: MIDI: ${String(t)}`),!1}}learn(e){const t=Object.keys(this.map).filter(a=>this.map[a]===e.id);if(this.learning?.classList.remove("midi-learning"),t.length||this.learning===e){for(const a of t)delete this.map[a];this.learning=null,this.save();return}this.learning=e,e.classList.add("midi-learning")}message(e){let t;try{t=cM(e)}catch(r){console.warn(`eigendance: MIDI: ${r.message}, ignored`);return}if(!t)return;if(this.learning){if(t.key.startsWith("note:")&&t.value===0)return;this.map[t.key]=this.learning.id,this.learning.classList.remove("midi-learning"),this.learning=null,this.save();return}const a=this.map[t.key],i=a?document.getElementById(a):null;i&&this.apply(i,t.key,t.value)}apply(e,t,a){const i=a>=.5,r=i&&!this.pressed.has(t);if(i?this.pressed.add(t):this.pressed.delete(t),e instanceof HTMLInputElement&&e.type==="range"){const s=Number(e.min||0),o=Number(e.max||100);e.value=String(s+a*(o-s)),e.dispatchEvent(new Event("input",{bubbles:!0}))}else e instanceof HTMLInputElement&&e.type==="checkbox"?r&&(e.checked=!e.checked,e.dispatchEvent(new Event("change"))):r&&e.click()}save(){try{localStorage.setItem(pl,JSON.stringify(this.map))}catch{}this.mark()}mark(){const e=new Set(Object.values(this.map));document.querySelectorAll(".midi-mapped").forEach(t=>t.classList.remove("midi-mapped")),e.forEach(t=>document.getElementById(t)?.classList.add("midi-mapped"))}}function gl(n){const e=n?.closest?.("input[type=range], input[type=checkbox], button");return e&&e.id?e:null}const lM=.02,vl=600;function dM(n,e,t){return e+(n.downbeat-t)/1e3}function fM(n,e,t,a){const i=60/n.bpm,r=Math.ceil((t-e)/i),s=Math.floor((a-e)/i),o=[],c=[];for(let l=r;l<=s;l++){const h=e+l*i;o.push(h),(l%n.beats_per_bar+n.beats_per_bar)%n.beats_per_bar===0&&c.push(h)}return{beats:Float32Array.from(o),downbeats:Float32Array.from(c)}}class uM{grid=null;origin=0;end=0;base=null;wrapped=null;set(e){e&&this.grid&&e.bpm===this.grid.bpm&&e.downbeat===this.grid.downbeat&&e.beats_per_bar===this.grid.beats_per_bar||(this.grid=e,this.wrapped=null)}frame(e,t){if(!this.grid)return;const a=dM(this.grid,e,t),i=60/this.grid.bpm;let r=Math.abs(a-this.origin)%(i*this.grid.beats_per_bar);r=Math.min(r,i*this.grid.beats_per_bar-r),(!this.wrapped||r>lM||e>this.end-vl/2)&&(this.origin=a,this.wrapped=null)}wrap(e){const t=this.grid;if(!t||!e)return e;if(this.wrapped&&this.base===e)return this.wrapped;this.base=e,this.end=Math.max(e.duration,0)+vl;const{beats:a,downbeats:i}=fM(t,this.origin,0,this.end),r={beats:a,downbeats:i,tempo:t.bpm,meter:t.beats_per_bar};return this.wrapped=new Proxy(e,{get:(s,o,c)=>o in r?r[o]:Reflect.get(s,o,c)}),this.wrapped}}const ef=30,As=64,bM=n=>n?.live===!0;class mM{spectrum=null;take="";takes=0;beats=0;onsets=0;bandsAt=-1/0;pending(e){return e!==this.spectrum||e.beats.length>this.beats||e.onsets.length>this.onsets}report(e){e!==this.spectrum&&(this.spectrum=e,this.take=`${performance.timeOrigin}-${++this.takes}`,this.beats=this.onsets=0,this.bandsAt=-1/0);const t=[];for(;this.beats<e.beats.length&&t.length<As;this.beats++)t.push([this.beats,e.beats[this.beats]]);const a=[];for(;this.onsets<e.onsets.length&&a.length<As;this.onsets++)a.push(e.onsets[this.onsets]);const i=[],r=1/ef,s=Math.max(0,Math.ceil((this.bandsAt+r)*e.rate));for(let o=s;o<e.frames&&i.length<As;o++){const c=o/e.rate;if(c<this.bandsAt+r-1e-9)continue;const l=e.values.subarray(o*e.bands,(o+1)*e.bands);i.push([c,Array.from(l,h=>Math.round(h*1e4)/1e4)]),this.bandsAt=c}return{take:this.take,beats:t,onsets:a,bands:i}}}const pM=4;function Mi(n,e){const t=n?.[e];return t&&typeof t.length=="number"?t:[]}function tf(n,e){let t=0,a=n.length;for(;t<a;){const i=t+a>>1;n[i]<e?t=i+1:a=i}return t<n.length?n[t]:null}function gM(n,e){const t=Mi(n,"downbeats"),a=t.length?t:Mi(n,"beats");return tf(a,e+1e-6)??e}function vM(n){const e=Mi(n,"downbeats");if(e.length)return Array.from(e);const t=Mi(n,"beats"),a=[];for(let i=0;i<t.length;i+=pM)a.push(t[i]);return a}function yM(n,e,t){if(e.until==="section")return tf(Mi(n,"sections"),t+1e-6);if(e.until!=="bars"||e.bars<1)return null;const a=vM(n);let i=0;for(;i<a.length&&a[i]<t-1e-6;)i++;const r=i+e.bars;return r<a.length?a[r]:null}function xM(n,e,t){return e>0?Math.min(1,Math.max(0,(t-n)/e)):1}const wM=250;function MM(n){const e=new URLSearchParams(n),t=/^(\d{2,5})x(\d{2,5})$/.exec(e.get("size")??""),a=Number(e.get("offset")??0);return{size:t?[Number(t[1]),Number(t[2])]:null,background:e.get("bg")==="studio"?"studio":"black",offset:Number.isFinite(a)?Math.min(Math.max(a,0),2e3)/1e3:0}}class _M{constructor(e,t){this.app=e,this.options=t}app;options;state=null;shownCue=null;shownPreset=null;pending=null;fade=null;cueStart=0;scheduled=0;mappings=new Map;lastFrame=0;lastT=0;clockAt=0;applied=[];clock=new uM;live=new mM;base=null;gains=[];start(e){const{app:t,options:a}=this;document.body.classList.add("show-output",`show-${a.background}`);const i=document.getElementById("player-area");if(a.size){const[d,f]=a.size;i.style.setProperty("--show-aspect",`${d} / ${f}`),i.classList.add("letterboxed")}if(a.background==="black"){t.viewer.studio.backdrop.visible=!1;const d=t.viewer.renderer,f=d.setClearColor.bind(d);d.setClearColor=(b,p)=>f(0,p)}const r=t.transport,s=r.now.bind(r);r.now=()=>Math.max(0,s()-this.options.offset),this.base=t.motion.spectrum,Object.defineProperty(t.motion,"spectrum",{configurable:!0,get:()=>this.clock.wrap(this.base),set:d=>{this.base=d}});const o=t.motion.weights.bind(t.motion);t.motion.weights=(d,f)=>this.weights(o,d,f);const c=t.viewer.onFrame;t.viewer.onFrame=d=>{this.frame(d),c(d)};const l=()=>{document.documentElement.requestFullscreen?.().catch(()=>{})};window.addEventListener("keydown",d=>{(d.key==="f"||d.key==="F")&&l()}),i.addEventListener("click",l),this.shownCue=e.cue,this.shownPreset=e.preset,this.follow(e),e.preset&&this.schedule(e.cue,e.preset,!0);const h=new EventSource("api/show/events");h.onmessage=d=>this.follow(JSON.parse(d.data))}follow(e){const t=this.state;this.state=e;const a=this.app;document.body.classList.toggle("show-blackout",e.blackout),this.clock.set(e.grid),t&&t.gain!==e.gain&&this.gains.push({gain:e.gain,heard:performance.timeOrigin+performance.now(),drawn:null}),e.playing&&!a.transport.playing&&a.play(),!e.playing&&a.transport.playing&&a.transport.pause();for(const[i,r]of Object.entries(e.controls))EM(i,r);(e.cue!==this.shownCue||e.preset!==this.shownPreset)&&this.schedule(e.cue,e.preset),e.next!==null&&!this.mappings.has(this.key(e.next,e.cues[e.next].preset))&&this.fetchMapping(e.next,e.cues[e.next].preset),a.viewer.requestDraw()}async schedule(e,t,a=!1){const i=this.app.viewer.time(),r=a?i:gM(this.app.motion.spectrum,i),s=++this.scheduled,o=this.mappings.get(this.key(e,t)),c=o!==void 0?o:await this.fetchMapping(e,t);s===this.scheduled&&(this.pending={cue:e,preset:t,at:r,mapping:c,sameModel:this.sameModel(e)})}sameModel(e){const t=this.state,a=e===null?null:t.cues[e],i=this.shownCue===null?null:t.cues[this.shownCue];return!a||!i||i.model.id===a.model.id&&i.song===a.song}key(e,t){const a=e===null?null:this.state?.cues[e]?.model;return`${t}\0${a?.kind??"mesh"}:${a?.id??this.app.library.meshId}`}async fetchMapping(e,t){if(!t)return null;const a=e===null?null:this.state?.cues[e]?.model,i=a?.kind==="rig"?`rig=${a.id}`:`mesh=${a?.id??this.app.library.meshId}`;let r=null;try{r=(await ia(`api/presets/${encodeURIComponent(t)}?${i}`)).mapping}catch(s){console.warn(`eigendance show: preset ${t}: ${String(s)}`)}return this.mappings.set(this.key(e,t),r),r}frame(e){const t=performance.now(),a=this.lastFrame?(t-this.lastFrame)/1e3:0;this.lastFrame=t,this.lastT>e+.5&&(this.cueStart=e),this.app.transport.playing&&this.clock.frame(e,performance.timeOrigin+t);const i=this.lastT;this.lastT=e;const r=this.gains[this.gains.length-1];r&&r.drawn===null&&(r.drawn=performance.timeOrigin+t),this.pending||this.endCue(e);const s=this.pending;s&&e>=s.at&&(this.pending=null,this.apply(s,e,a,i));const o=this.base,c=bM(o)&&this.app.live.active?o:null,l=c?1e3/ef:wM;if(t-this.clockAt>l||c&&this.live.pending(c)){this.clockAt=t;const h=this.app.motion.spectrum;fetch("api/show/clock",{method:"POST",headers:{"Content-Type":"application/json"},body:JSON.stringify({song:c?null:this.app.library.songId||null,time:e,playing:this.app.transport.playing,tempo:h?.tempo||null,wall:performance.timeOrigin+t,live:c?this.live.report(c):null})}).catch(()=>{})}}endCue(e){const t=this.state;if(!t||t.cue===null||this.shownCue!==t.cue)return;const a=t.cues[t.cue],i=yM(this.app.motion.spectrum,a,this.cueStart);if(i===null||e<i||t.loop_cue||t.next===null)return;this.cueStart=e,this.pending=null,cn("api/show/control",{action:"next",value:{from:t.cue}}).catch(()=>{});const r=t.next,s=t.cues[r].preset;this.state={...t,cue:r,preset:s};const o=this.mappings.get(this.key(r,s));o!==void 0||!s?this.pending={cue:r,preset:s,at:e,mapping:o??null,sameModel:this.sameModel(r)}:this.schedule(r,s,!0)}async apply(e,t,a,i=t){const r=this.app,s=this.state,o=s.fade_beats,c=r.motion.spectrum?.tempo||s.tempo||120,l=e.sameModel?r.player.prepared:null;if(this.applied.push({cue:e.cue,preset:e.preset,t,at:performance.now(),frameDt:a,before:i}),e.cue!==this.shownCue&&(this.cueStart=t),this.shownCue=e.cue,this.shownPreset=e.preset,!e.sameModel&&e.cue!==null){const h=s.cues[e.cue];h.live?await r.startLive({kind:h.live}):h.song&&(h.song!==r.library.songId||r.live.active)&&(r.live.stop(),await r.library.loadSong(h.song)),h.model.kind==="mesh"&&h.model.id!==r.library.meshId?(await r.library.loadMesh(h.model.id),r.player.basisChanged()):h.model.kind==="rig"&&(await r.openRig(h.model.id),r.setView("player")),s.playing&&r.play()}if(r.rigs.active)e.mapping&&await r.rigs.openDance(e.mapping,e.preset??"");else{const h=e.mapping??r.gallery.mappings()[0]??null;h&&r.open(h,e.preset??"")}this.fade=o>0?{from:l,start:t,length:o*60/c}:null,r.viewer.requestDraw()}weights(e,t,a){const i=this.state?.gain??1,r=e(t,a),s=this.fade,o=s?xM(s.start,s.length,a):1;s&&o>=1&&(this.fade=null);const c=s&&o<1&&s.from&&s.from.k===t.k?e(s.from,a):null;for(let l=0;l<r.length;l++)r[l]=i*(o*r[l]+(c?(1-o)*c[l]:0));return r}}function EM(n,e){const t=document.getElementById(n);t instanceof HTMLInputElement?(t.type==="checkbox"?t.checked=e>=.5:t.value=String(e),t.dispatchEvent(new Event(t.type==="checkbox"?"change":"input"))):t instanceof HTMLButtonElement&&e>=.5&&t.click()}const SM=n=>/\/show\/?$/.test(n);async function AM(n,e){const t=await ia("api/show/state"),a=t.cue===null?null:t.cues[t.cue],i=new Zd({...n,size:null,view:"player",bare:!0,scale:n.scale??1,mesh:a?.model.kind==="mesh"?a.model.id:n.mesh,song:a?.song??n.song,source:a?.live??n.source}),r=new _M(i,MM(location.search));window.eigendanceShow={output:r};const s=i.start().then(async()=>{a?.model.kind==="rig"&&(await i.openRig(a.model.id),i.setView("player")),r.start(t)});e&&e(i,s)}function TM(n){const e=new rM,t=new nM(n),a=new hM;window.eigendanceShow={panel:e,presets:t,midi:a},sM(),e.onPreset=i=>{i&&t.play(i).catch(()=>{})},e.start(),a.start()}const ir=Wf(location.search);if(SM(location.pathname))AM(ir,xc(ir)?ml:null);else{const n=new Zd(ir),e=n.start();xc(ir)&&ml(n,e),TM(n)}
